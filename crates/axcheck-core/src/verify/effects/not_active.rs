//! `not_active`: the table was not loaded, not enabled, or the axis not referenced since
//! (Siemens MD32700, ecmc's enable, FANUC's power cycle, LinuxCNC's `COMP_FILE` in the
//! wrong joint section): the re-measurement shows no change at all.

use super::{Candidate, EffectContext, Key, VerifyEffect};

pub struct NotActive;

impl VerifyEffect for NotActive {
    fn candidates(&self, ctx: &EffectContext) -> Vec<Candidate> {
        vec![Candidate {
            key: Key::NotActive,
            change: vec![0.0; ctx.rows.len()],
            params: Vec::new(),
            what: "the table did not act: the deviations are as before (not loaded, not enabled, or the axis not referenced since)".into(),
        }]
    }
}
