//! `sign_inverted`: the table acted with the opposite sign (a controller that adds what
//! another subtracts: ecmc before and after 10.0.0, LinuxCNC's documentation against its
//! code, an unconfirmed FANUC sign), so the error doubled instead of vanishing.

use super::{Candidate, EffectContext, Key, VerifyEffect};

pub struct SignInverted;

impl VerifyEffect for SignInverted {
    fn candidates(&self, ctx: &EffectContext) -> Vec<Candidate> {
        vec![Candidate {
            key: Key::SignInverted,
            change: ctx.applied().iter().map(|c| -c).collect(),
            params: vec![("factor", -1.0)],
            what: "the table acted with the opposite sign: the error grew by what it should have removed".into(),
        }]
    }
}
