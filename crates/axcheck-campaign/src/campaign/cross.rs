//! An axis entry's `compensation:` as a straightness test's cross table takes it
//! (`input`, `output`, `interval`, `active`, `verifies`) and a positioning test's pitch
//! table does not: each key on the wrong test stops at its line.

use super::AxisRaw;
use super::model::{ActiveRaw, CompensationRaw};
use crate::geometry::TestKind;
use crate::yaml::{Located, LocationIndex};

/// The keys written under `compensation` that only a pitch table takes (relative paths).
fn pitch_only(c: &CompensationRaw) -> Vec<&'static str> {
    let backlash = |a: &Option<ActiveRaw>| matches!(a, Some(ActiveRaw::Stated(s)) if s.backlash_um.is_some() || s.backlash_arcsec.is_some());
    let given = [
        ("axis", c.axis.is_some()),
        ("reference", c.reference.is_some()),
        ("measuring_system", c.measuring_system.is_some()),
        ("comp_file_type", c.comp_file_type.is_some()),
        ("active", backlash(&c.active)),
        (
            "verifies",
            c.verifies.as_ref().is_some_and(|v| {
                v.backlash_um.is_some() || v.backlash_arcsec.is_some() || backlash(&v.active)
            }),
        ),
    ];
    given.iter().filter(|(_, g)| *g).map(|(k, _)| *k).collect()
}

/// Checks `compensation`'s keys against the test they are written on.
pub(super) fn check(raw: &AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    let Some(c) = &raw.compensation else {
        return Ok(());
    };
    let refuse = |key: &str, why: &str| {
        let path = format!("{base}.compensation.{key}");
        Err(Located::new(
            index.key(&path).or_else(|| index.key(base)),
            format!("{path}: {why}"),
        ))
    };
    match raw.test {
        TestKind::Positioning => {
            let cross = [("input", c.input.is_some()), ("output", c.output.is_some())];
            match cross.iter().find(|(_, given)| *given) {
                Some((key, _)) => refuse(
                    key,
                    "names a cross table's axis; a cross table is of a straightness test (`test: straightness`), a positioning test's table names its axis with `axis`",
                ),
                None => Ok(()),
            }
        }
        TestKind::Straightness => match pitch_only(c).first() {
            Some(key) => refuse(
                key,
                "is of a positioning test's pitch table; a straightness test's cross table takes `input`, `output`, `interval`, `active: none|{file}` and `verifies: {before, table, active}`",
            ),
            None => Ok(()),
        },
        _ => Ok(()),
    }
}
