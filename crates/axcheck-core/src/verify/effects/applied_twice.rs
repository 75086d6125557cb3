//! `applied_twice`: the correction acted twice: an absolute table loaded on top of the one
//! it already contained, a table loaded in two places (a table and a backlash or a second
//! measuring system), or an incremental table added to itself.

use super::{Candidate, EffectContext, Key, VerifyEffect};

pub struct AppliedTwice;

impl VerifyEffect for AppliedTwice {
    fn candidates(&self, ctx: &EffectContext) -> Vec<Candidate> {
        vec![Candidate {
            key: Key::AppliedTwice,
            change: ctx.applied().iter().map(|c| 2.0 * c).collect(),
            params: vec![("factor", 2.0)],
            what: "the correction acted twice: the error changed sign instead of vanishing".into(),
        }]
    }
}
