//! The report's view of a positioning test carried to the tool point (Abbe,
//! `geometry::abbe`): each parameter at the beam and at the tool point with its limit and
//! outcome there, the offsets and the angular tests it went through, or why it could not
//! be carried.

use super::num;
use crate::evaluate::Evaluation;
use crate::judge::Conformance;
use crate::results::{AxisTest, ToolPoint};
use crate::units::AxisKind;
use serde::Serialize;

#[derive(Serialize)]
pub(crate) struct ToolPointSection<'a> {
    /// `Y 0 mm, Z 160 mm`.
    offsets: String,
    /// `EBX and ECX`.
    rotations: String,
    rows: Vec<Row>,
    beam_verdict: &'static str,
    tool_verdict: &'static str,
    changes: bool,
    notes: &'a [String],
    error: Option<&'a str>,
}

#[derive(Serialize)]
struct Row {
    symbol: &'static str,
    beam: String,
    tool: String,
    limit: String,
    outcome: Option<Conformance>,
}

/// The section of `t`, when it has a tool point.
pub(crate) fn tool_point_section(t: &AxisTest) -> Option<ToolPointSection<'_>> {
    let e = t.evaluated()?;
    let carried = e.tool_point.as_deref()?;
    let beam_verdict = t.verdict().words();
    Some(match carried {
        Ok(p) => ToolPointSection {
            offsets: (p.offsets_mm.iter())
                .map(|(letter, mm)| format!("{letter} {}", super::pos(AxisKind::Linear, *mm)))
                .collect::<Vec<_>>()
                .join(", "),
            rotations: p.rotations.join(" and "),
            rows: rows(&e.evaluation, p),
            beam_verdict,
            tool_verdict: p.verdict.words(),
            changes: p.verdict != t.verdict(),
            notes: &p.notes,
            error: None,
        },
        Err(why) => ToolPointSection {
            offsets: String::new(),
            rotations: String::new(),
            rows: Vec::new(),
            beam_verdict,
            tool_verdict: "",
            changes: false,
            notes: &[],
            error: Some(why),
        },
    })
}

/// Each parameter at the tool point beside the measured one, in the standard's order.
fn rows(measured: &Evaluation, p: &ToolPoint) -> Vec<Row> {
    let check = |key| (p.judgement.as_ref()).and_then(|j| j.checks.iter().find(|c| c.key == key));
    (p.evaluation.parameters.iter())
        .map(|q| Row {
            symbol: q.symbol(),
            beam: measured
                .parameter(q.def.key)
                .map_or("–".into(), |m| num(m.value)),
            tool: num(q.value),
            limit: check(q.def.key).map_or("–".into(), |c| num(c.limit)),
            outcome: check(q.def.key).map(|c| c.outcome),
        })
        .collect()
}
