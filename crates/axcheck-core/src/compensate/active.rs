//! What the controller held while the axis was measured. ISO 230-2 3.2 has the report state
//! which compensation was active during the test: the mean deviations measured with a table
//! active are what that table left, so the table the controller must hold is the active
//! one plus what this measurement alone would give (incremental), and the prediction
//! applies only their difference. Unstated, it is said, not guessed: the table is this
//! measurement's alone, to be added to whatever was active.

use super::controllers::{Backlash, Controller};
use super::{Table, Warning};
use crate::units::{AxisKind, fmt_fixed};
use serde::Serialize;

/// The compensation active during a test, as stated (`active: none` is the default).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Active {
    /// The table the controller held, read from its file; `None`: no table.
    pub table: Option<Table>,
    /// The file it was read from, as the user named it.
    pub file: Option<String>,
    /// The backlash parameter's value, µm or arcsec (what it adds on ↑ approaches relative
    /// to ↓ ones, c↑ − c↓: MD32450, LinuxCNC `BACKLASH`, …); `None`: not stated.
    pub backlash: Option<f64>,
}

/// Whether a table is the whole correction or builds on an active one.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    /// The whole correction: nothing was active (or the state was not stated: then a
    /// warning says to add it to whatever was).
    Absolute,
    /// The active compensation plus this measurement's correction.
    Incremental,
}

impl Active {
    /// Whether anything was active that the new table builds on.
    pub fn mode(&self) -> Mode {
        if self.table.is_some() || self.backlash.is_some_and(|b| b != 0.0) {
            Mode::Incremental
        } else {
            Mode::Absolute
        }
    }

    /// Whether the backlash parameter acted on the readings: not where the controller has
    /// none, not where it keeps it (the same before and after), not on LinuxCNC beside a
    /// table (it is unused then).
    fn backlash_counts(&self, rule: Backlash) -> bool {
        match rule {
            Backlash::Stated | Backlash::Cleared => true,
            Backlash::UnusedWithTable => self.table.is_none(),
            Backlash::Kept | Backlash::Absent => false,
        }
    }

    /// The correction the controller added during the test, as a table: the active table,
    /// and ± half the backlash where it acted and the new table or parameter takes it
    /// over (a constant apart, which no ISO 230-2 parameter sees, the controllers add it
    /// on one side of a reversal).
    pub fn total(&self, rule: Backlash, kind: AxisKind) -> Option<Table> {
        let b = self
            .backlash
            .filter(|_| self.backlash_counts(rule))
            .unwrap_or(0.0);
        let mut total = match &self.table {
            Some(t) => t.clone(),
            None if b != 0.0 => Table {
                kind,
                positions: vec![0.0],
                up: vec![0.0],
                down: vec![0.0],
                reference: 0.0,
                modulo_deg: None,
                place: Default::default(),
                interpolation: Default::default(),
            },
            None => return None,
        };
        for v in total.up.iter_mut() {
            *v += b / 2.0;
        }
        for v in total.down.iter_mut() {
            *v -= b / 2.0;
        }
        Some(total)
    }
}

/// Why the stated active compensation does not fit `controller`, if it does not.
pub fn refusal(controller: &dyn Controller, active: &Active, kind: AxisKind) -> Option<String> {
    let b = active.backlash.filter(|b| *b != 0.0)?;
    (controller.backlash() == Backlash::Absent).then(|| {
        format!(
            "a backlash of {} {} was stated, but {} has no backlash parameter beside its table; leave backlash_{} out",
            fmt_fixed(b, 3),
            kind.deviation_symbol(),
            controller.name(),
            kind.deviation_unit()
        )
    })
}

/// What the conditions' compensation text says (ISO 230-2 3.2): `Some(false)` for "none",
/// "off", "inactive", …, `Some(true)` for a named compensation ("reversal and lead screw",
/// "LEC active"), `None` when empty.
pub(crate) fn says_active(text: &str) -> Option<bool> {
    let t = text.trim().to_lowercase();
    if t.is_empty() {
        return None;
    }
    let words: Vec<&str> = t.split(|c: char| !c.is_alphanumeric()).collect();
    let off_word = [
        "none",
        "off",
        "inactive",
        "disabled",
        "deactivated",
        "cleared",
        "without",
    ];
    let off = words.iter().any(|w| off_word.contains(w))
        || ["not active", "no compensation"]
            .iter()
            .any(|p| t.contains(p));
    Some(!off)
}

/// The warnings of the active state: unknown, contradicted by the conditions, its backlash
/// unstated or unused. `active`: `None` when not stated; `conditions`: the test conditions'
/// compensation text.
pub fn warnings(
    controller: &dyn Controller,
    active: Option<&Active>,
    conditions: Option<&str>,
    kind: AxisKind,
) -> Vec<Warning> {
    let Some(active) = active else {
        return vec![unknown(controller, kind)];
    };
    let mut out = Vec::new();
    let stated_on = active.mode() == Mode::Incremental;
    if let Some(said) = conditions.and_then(says_active)
        && said != stated_on
    {
        out.push(contradiction(conditions.unwrap_or_default(), stated_on));
    }
    let rule = controller.backlash();
    if active.table.is_some() && active.backlash.is_none() && rule == Backlash::Stated {
        out.push(Warning {
            key: "active_backlash_unknown",
            message: format!(
                "the backlash parameter active during the test was not stated: the value the file gives for it is the measured reversal alone, to be added to what the parameter held (state it as backlash_{})",
                kind.deviation_unit()
            ),
        });
    }
    if active.table.is_some() && active.backlash.is_some() && rule == Backlash::UnusedWithTable {
        out.push(Warning {
            key: "active_backlash_unused",
            message: format!(
                "{} does not use its backlash parameter while a table is loaded: the stated backlash is left out; set it to 0",
                controller.name()
            ),
        });
    }
    out
}

/// The active state was not stated.
fn unknown(controller: &dyn Controller, kind: AxisKind) -> Warning {
    let backlash = match controller.backlash() {
        Backlash::Stated => " and backlash",
        _ => "",
    };
    Warning {
        key: "active_compensation_unknown",
        message: format!(
            "the compensation active during the test was not stated: these values are this measurement's correction alone, to be added to whatever table{backlash} the controller held; loaded in place of an active table they lose its correction. State it (compensation: {{active: {{file: TABLE, backlash_{}: N}}}} or {{active: none}}, or --active), or measure again with the compensation off",
            kind.deviation_unit()
        ),
    }
}

/// The conditions' text and the stated active state disagree.
fn contradiction(text: &str, stated_on: bool) -> Warning {
    let stated = if stated_on {
        "an active compensation is stated"
    } else {
        "`active: none` is stated"
    };
    Warning {
        key: "active_compensation_contradiction",
        message: format!(
            "the test conditions say the compensation was \"{}\" (ISO 230-2 3.2), but {stated}: check which was active before loading this table",
            text.trim()
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The conditions' words: a named compensation is on; none, off, disabled … are off.
    #[test]
    fn what_the_conditions_say() {
        for on in [
            "reversal and lead-screw compensation active",
            "reversal and lead screw",
            "LEC on",
            "joint compensation table X.txt (COMP_FILE_TYPE = 1)",
        ] {
            assert_eq!(says_active(on), Some(true), "{on}");
        }
        for off in [
            "none",
            "off",
            "Compensation OFF",
            "LEC disabled",
            "not active",
            "no compensation",
            "pitch error data cleared",
        ] {
            assert_eq!(says_active(off), Some(false), "{off}");
        }
        assert_eq!(says_active("  "), None);
    }

    /// ± half the backlash where it acted: both directions of a table, or a table of one
    /// point with none; nothing where the controller keeps it or has none.
    #[test]
    fn the_total_correction_active() {
        let active = Active {
            table: None,
            file: None,
            backlash: Some(4.0),
        };
        let total = active.total(Backlash::Stated, AxisKind::Linear).unwrap();
        assert_eq!(
            (total.up.clone(), total.down.clone()),
            (vec![2.0], vec![-2.0])
        );
        assert_eq!(total.reversal_correction(), -4.0);
        assert!(active.total(Backlash::Kept, AxisKind::Linear).is_none());
        assert_eq!(active.mode(), Mode::Incremental);
        assert_eq!(Active::default().mode(), Mode::Absolute);
        let with_table = Active {
            table: Some(total),
            ..active
        };
        let unused = with_table
            .total(Backlash::UnusedWithTable, AxisKind::Linear)
            .unwrap();
        assert_eq!((unused.up, unused.down), (vec![2.0], vec![-2.0]));
    }
}
