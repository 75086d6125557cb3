//! Each positioning test fitted on its axis's angular tests in the campaign
//! ([`crate::diagnose::abbe`]): whether its mean deviations follow the pitch or yaw as a
//! beam off the line the axis positions on reads them (an Abbe error), with the lever.

use super::Tested;
use super::tool_point::{Angular, angular_of};
use crate::campaign::geometry::{across, axis_letter, rotation_about};
use crate::diagnose::abbe::{self, Rotation};
use crate::geometry::TestKind;
use crate::units::Direction;

/// Every positioning test of an axis with an angular test about an axis across it.
pub(crate) fn fit_all(tests: &mut [Tested]) {
    let angular: Vec<Angular> = tests.iter().filter_map(|(t, _)| angular_of(t)).collect();
    for (t, _) in tests.iter_mut() {
        if t.test_kind() != TestKind::Positioning {
            continue;
        }
        let Some(spec) = t.spec.clone() else { continue };
        let Some(own) = axis_letter(&spec.raw.name) else {
            continue;
        };
        let machine = t.machine.id.clone();
        let [v, w] = across(own);
        // About v the lever lies along w and adds; about w along v and subtracts.
        let found: Vec<(&Angular, char, f64)> = [(v, w, 1.0), (w, v, -1.0)]
            .into_iter()
            .filter_map(|(about, lever, sign)| {
                let a = angular.iter().find(|a| {
                    a.machine == machine
                        && a.axis == spec.raw.name
                        && a.about == rotation_about(about)
                })?;
                Some((a, lever, sign))
            })
            .collect();
        let angles: Vec<_> = (found.iter())
            .map(|(a, _, _)| move |x: f64, d: Direction| a.trace.at(x, d))
            .collect();
        let rotations: Vec<Rotation> = (found.iter().zip(&angles))
            .map(|((a, lever, sign), angle)| Rotation {
                symbol: &a.symbol,
                lever: *lever,
                sign: *sign,
                angle_arcsec: angle,
            })
            .collect();
        if rotations.is_empty() {
            continue;
        }
        let Some(e) = t.evaluated_mut() else { continue };
        let Some(data) = e.data.as_ref() else {
            continue;
        };
        e.abbe = abbe::fit(data, &rotations).map(Box::new);
    }
}
