//! The plan for the laser software, so that the capture side and the evaluation agree on
//! target numbers and order: every reading in the order of the cycle as CSV, and the target
//! list in the `TARGET DATA::` block of a Renishaw `.rtl` / `.rta` file (the layout
//! axcheck's Renishaw reader reads: `Target-count`, the positions after `Targets :` five a
//! line, `Flags:`; the list rising, so odd runs are the ↑ ones).

use super::Plan;
use crate::axis_model::Step;
use crate::units::fmt_fixed;
use std::fmt::Write;

/// `reading,run,direction,target,position_mm`: one row per reading, in the order the
/// part program takes them (target numbered from 1 as the data file numbers it).
pub fn readings_csv(plan: &Plan) -> String {
    let unit = plan.axis.kind.position_unit();
    let mut out = format!("reading,run,direction,target,position_{unit}\n");
    let reads = plan
        .test_plan()
        .steps(&plan.targets)
        .into_iter()
        .filter_map(|s| match s {
            Step::Read {
                position,
                target,
                direction,
                run,
            } => Some((position, target, direction, run)),
            Step::Move(_) => None,
        });
    for (k, (position, target, direction, run)) in reads.enumerate() {
        let _ = writeln!(
            out,
            "{},{},{},{},{}",
            k + 1,
            run + 1,
            direction.name(),
            target + 1,
            fmt_fixed(position, 3)
        );
    }
    out
}

/// The `TARGET DATA::` block of a Renishaw file holding the plan's targets.
pub fn rtl_targets(plan: &Plan) -> String {
    let mut out = format!(
        "TARGET DATA::\nFiletype  : ISO\nTarget-count: {}\nTargets :\n",
        plan.targets.len()
    );
    for line in plan.targets.chunks(5) {
        let values: Vec<String> = line.iter().map(|t| fmt_fixed(*t, 6)).collect();
        let _ = writeln!(out, "{}", values.join("  "));
    }
    out.push_str("Flags: 0 0 2 0\n");
    out
}
