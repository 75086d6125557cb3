//! Each stage's configuration taken from the campaign, one file per stage, in the
//! pipeline's order: the reading of a test's file ([`read`]), the plan rules' context and
//! the clause 7.1 conditions left unstated ([`rules`]), the NDE correction ([`nde`]),
//! the evaluation ([`evaluate`]), the uncertainty's set-up ([`uncertainty`]), the specs,
//! limits and decision rule ([`judge`]), the diagnosis's options ([`diagnose`]) and the
//! compensation's tables ([`compensate`]; a straightness test's cross tables, [`cross`]). The stages themselves are the core's and know
//! nothing of campaigns; the batch calls these adapters.

pub mod compensate;
pub mod cross;
pub mod diagnose;
pub mod evaluate;
pub mod judge;
pub mod nde;
pub mod read;
pub mod rules;
pub mod uncertainty;
