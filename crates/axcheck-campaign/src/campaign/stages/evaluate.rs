//! The evaluation as the campaign asks for it: the axis's standard, and for GOST 27843 S
//! from ranges when the axis says `s_from_ranges` (GOST 27843-88, 2.5).

use crate::campaign::AxisSpec;
use crate::evaluate::Evaluation;
use crate::evaluate::gost27843::SMethod;
use crate::measurement::AxisData;

/// The parameters by the axis's standard (GOST 27843 with S from ranges when asked).
pub fn evaluate(axis: &AxisSpec, data: &AxisData) -> Evaluation {
    let s_method = match axis.raw.s_from_ranges {
        true => SMethod::Ranges,
        false => SMethod::Formula5,
    };
    crate::evaluate::evaluate_by(data, axis.standard, s_method)
}
