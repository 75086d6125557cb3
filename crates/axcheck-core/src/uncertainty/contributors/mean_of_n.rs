//! `mean_of_n`: the scatter of the means the parameter is built from.
//!
//! Each mean X̄ of n readings carries u = s/√n (a Type A evaluation, GUM 4.2.3): a range
//! (A, E, M) has one mean at each end, a reversal Bi = X̄i↑ − X̄i↓ two at one target, B̄
//! the mean of m such differences, a bidirectional repeatability Ri = kS↑ + kS↓ + |Bi|
//! its |Bi|. Input: the resulting standard uncertainty (computed in
//! `uncertainty::extent`), normal with k = 1; sensitivity 1. Independent of the length;
//! ISO 230-2 and GOST 27843 parameters with n ≥ 2 only.

use super::{Context, Contributor};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct MeanOfN;

impl Contributor for MeanOfN {
    fn name(&self) -> &'static str {
        "mean_of_n"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        ctx.extent.means_u.map(|u| Input {
            value: u,
            unit: ctx.unit(),
            distribution: Distribution::STANDARD,
        })
    }

    fn sensitivity(&self, _: &Context) -> f64 {
        1.0
    }
}
