//! Judging against acceptance specs. The judging itself (limits, decision rules, checks,
//! the verdict) is the core's [`axcheck_core::judge`]; here the specs are read
//! (`specs/*.yaml`, built in or the campaign's) and a test's limits taken from one
//! ([`limits`]).

pub use axcheck_core::judge::*;

mod spec;
pub use spec::{BUILTIN_SPECS, Band, NoBand, Spec, check_tolerances, limits};
