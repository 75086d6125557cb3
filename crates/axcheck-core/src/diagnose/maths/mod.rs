//! The diagnosis's shared maths, which knows nothing of effects: least squares
//! ([`linalg`]), the distributions its tests are read against ([`stats`]; a linear
//! combination of χ² variables: [`imhof`]) and the periodogram of unevenly spaced target
//! means ([`periodogram`]); the values of the costliest remembered by their inputs ([`memo`]).

pub(crate) mod imhof;
pub(crate) mod linalg;
pub(crate) mod memo;
pub(crate) mod periodogram;
pub mod stats;
