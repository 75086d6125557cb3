//! `wrong_axis`: the table loaded on this axis is another axis's (X's table in Y's place, a
//! Siemens file naming the wrong machine axis, a HEIDENHAIN column key or a TwinCAT
//! `kopf.achs_nr` mistaken): the change follows the other axis's table. Tried against the
//! tables loaded for the machine's other axes (in a campaign, those their `verifies`
//! names; on the command line, `--other`).

use super::{Candidate, EffectContext, Key, VerifyEffect};

pub struct WrongAxis;

impl VerifyEffect for WrongAxis {
    fn candidates(&self, ctx: &EffectContext) -> Vec<Candidate> {
        ctx.others
            .iter()
            .filter(|o| o.new.kind == ctx.new.kind)
            .map(|o| Candidate {
                key: Key::WrongAxis,
                change: ctx.change_with(&o.new, 0.0),
                params: Vec::new(),
                what: format!("the table that acted is axis {}'s, not this axis's", o.axis),
            })
            .collect()
    }
}
