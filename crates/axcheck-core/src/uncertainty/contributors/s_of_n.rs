//! `s_of_n`: the statistical uncertainty of the estimates S.
//!
//! S from n readings estimates σ with the chi distribution: E\[S\] = c4·σ and the standard
//! deviation of S is σ·√(1 − c4²), so u(S) = S·√(1 − c4²)/c4 with
//! c4 = √(2/(n−1))·Γ(n/2)/Γ((n−1)/2) (GUM E.4.3 gives the first-order 1/√(2(n−1))). An
//! accuracy A = max(X̄ + kS) − min(X̄ − kS) carries k·u(S) at each end, a repeatability
//! 2kS carries 2k·u(S), R̄ the mean of 2m such. Input: the resulting standard
//! uncertainty (computed in `uncertainty::extent`), normal with k = 1; sensitivity 1.
//! Independent of the length; ISO 230-2 and GOST 27843 parameters with n ≥ 2 only.

use super::{Context, Contributor};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct SOfN;

impl Contributor for SOfN {
    fn name(&self) -> &'static str {
        "s_of_n"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        ctx.extent.scatter_u.map(|u| Input {
            value: u,
            unit: ctx.unit(),
            distribution: Distribution::STANDARD,
        })
    }

    fn sensitivity(&self, _: &Context) -> f64 {
        1.0
    }
}
