//! The parameter catalogue: every parameter axcheck computes, defined once.
//!
//! A [`ParameterDef`] holds what never changes about a parameter — its stable key (JSON,
//! specs, table columns), its symbol, its name in words, the clause that defines it, the
//! standards that define it that way, its unit kind and what sort of quantity it is. The
//! evaluators attach values to these definitions ([`super::Parameter`]); the judge, the
//! exporters, the markdown summary, the reports and the command line read keys, symbols
//! and clauses from here and nowhere else.
//!
//! A key names one quantity per standard: ISO 230-2's `A` and GOST 27843's `A` are the
//! same idea defined in two documents (two entries, one key), NMTBA's `A` is the NMTBA
//! accuracy. Within one standard a key is unique. The order of [`CATALOGUE`] is the order
//! in which each standard lists its parameters.

use super::{ParamKey, StandardId};
use crate::units::AxisKind;
use std::sync::LazyLock;

/// The unit a parameter's value is expressed in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UnitKind {
    /// A positional deviation: µm on a linear axis, arcsec on a rotary one (ISO 230-2
    /// clause 2.5; rotary axes, clause 1).
    Deviation,
}

impl UnitKind {
    /// The unit's key for an axis of `kind`: `um` or `arcsec`.
    pub fn unit(self, kind: AxisKind) -> &'static str {
        match self {
            UnitKind::Deviation => kind.deviation_unit(),
        }
    }
}

/// What sort of value a parameter is: it decides whether a tolerance may limit it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// A width or largest magnitude, never negative (A, E, M, R, B, 6σ …): limited by a
    /// tolerance.
    Width,
    /// A signed mean (B̄, L̄): limited by its magnitude.
    Signed,
    /// Where a band lies, not how wide it is (X̄max, Ā, the VDI limits, NMTBA's zero
    /// line): a tolerance cannot name it.
    Level,
}

/// The headline a parameter fills in summaries that show one number per idea across
/// standards (A, E, M, R and B of the summary table and the Markdown summary).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// Bidirectional accuracy of positioning (ISO 230-2 A, GOST A, NMTBA A_b).
    Accuracy,
    /// Bidirectional systematic positional deviation (ISO 230-2 E).
    Systematic,
    /// Range of the mean bidirectional positional deviation (ISO 230-2 M).
    MeanRange,
    /// Bidirectional repeatability (ISO 230-2 R, GOST R_max).
    Repeatability,
    /// Reversal value of the axis (ISO 230-2 B, GOST B_max).
    Reversal,
}

/// The approaches a parameter describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Approach {
    /// Both directions together (bidirectional).
    Both,
    /// Approaches in the positive direction only (↑).
    Up,
    /// Approaches in the negative direction only (↓).
    Down,
}

/// One parameter as a standard defines it.
#[derive(Debug, PartialEq)]
pub struct ParameterDef {
    /// Stable key in JSON, specs and table columns: `A`, `A_up`, `R_max`, `B_mean` …
    pub key: ParamKey,
    /// Symbol for people: `A↑`, `B̄` …
    pub symbol: &'static str,
    /// Name in words.
    pub name: &'static str,
    /// The clause (and formula) that defines it.
    pub clause: &'static str,
    /// The standards that define it this way.
    pub standards: &'static [StandardId],
    pub unit: UnitKind,
    pub quantity: Quantity,
    pub role: Option<Role>,
    pub approach: Approach,
    /// Needs repeated approaches: not applicable with n = 1 (ISO 230-2 clause 5.2).
    pub(crate) needs_repeats: bool,
    /// What its value is made of, for the extent of its uncertainty
    /// (`crate::uncertainty::extent`).
    pub spread: Spread,
}

/// What a parameter's value is made of, which decides how far an error of the laser's
/// reading moves it (the extent of its uncertainty budget, `crate::uncertainty::extent`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spread {
    /// The range of X̄ ± kS over the targets (A, A↑, A↓).
    Band,
    /// The range of the mean deviations X̄ of a direction (E, E↑, E↓).
    Mean,
    /// The range of the bidirectional mean deviations (M).
    Bidirectional,
    /// A repeatability at its target (R, R↑, R↓, R_max).
    Repeatability,
    /// The mean repeatability over the targets (GOST R̄).
    MeanRepeatability,
    /// The reversal value at its target (B, B_max).
    ReversalAtTarget,
    /// The mean reversal value over the targets (B̄).
    ReversalMean,
    /// Lost motion, a reversal value without statistics (NMTBA L, L̄).
    LostMotion,
    /// The scatter alone: `factor` σ, times the standard's coverage factor k when `of_k`
    /// (VDI 3441 R_p = 2k σ, NMTBA spreads = k σ, VDI σ̄).
    Scatter { factor: f64, of_k: bool },
    /// Anything else: bounded by the measurement travel.
    Travel,
}

impl ParameterDef {
    /// Whether an acceptance spec or an axis's tolerances may give it a limit.
    pub fn limitable(&self) -> bool {
        self.quantity != Quantity::Level
    }

    pub(crate) fn defined_by(&self, standard: StandardId) -> bool {
        self.standards.contains(&standard)
    }

    /// Whether it measures the scatter of the readings about their directional means,
    /// which a compensation table cannot correct (it moves the means only): a
    /// unidirectional repeatability or spread (R↑, R↓, 3σ↑, 3σ↓), or σ itself (VDI σ̄,
    /// the mean of each direction's σi). Not a bidirectional repeatability or spread,
    /// which holds the reversal a table moves, nor VDI's R_p = 6σ̄, which σ̄ already says.
    pub fn is_scatter(&self) -> bool {
        match self.spread {
            Spread::Repeatability | Spread::Scatter { .. } if self.approach != Approach::Both => {
                true
            }
            Spread::Scatter { factor, of_k } => factor == 1.0 && !of_k,
            _ => false,
        }
    }
}

const ISO: &[StandardId] = &[StandardId::Iso230_2, StandardId::Gbt17421_2];
const GOST: &[StandardId] = &[StandardId::Gost27843];
const VDI: &[StandardId] = &[StandardId::Vdi3441];
const NMTBA: &[StandardId] = &[StandardId::Nmtba];

/// A definition with the fields most entries share (deviation unit, a width, no role,
/// computable with n = 1).
const fn def(
    key: ParamKey,
    symbol: &'static str,
    name: &'static str,
    clause: &'static str,
    standards: &'static [StandardId],
) -> ParameterDef {
    ParameterDef {
        key,
        symbol,
        name,
        clause,
        standards,
        unit: UnitKind::Deviation,
        quantity: Quantity::Width,
        role: None,
        approach: Approach::Both,
        needs_repeats: false,
        spread: Spread::Travel,
    }
}

/// `d`, whose value is made of `spread`.
const fn made_of(spread: Spread, d: ParameterDef) -> ParameterDef {
    ParameterDef { spread, ..d }
}

/// A unidirectional parameter: `d` in `approach` only.
const fn only(approach: Approach, d: ParameterDef) -> ParameterDef {
    ParameterDef { approach, ..d }
}

const fn with_role(d: ParameterDef, role: Role) -> ParameterDef {
    ParameterDef {
        role: Some(role),
        ..d
    }
}

const fn repeated(d: ParameterDef) -> ParameterDef {
    ParameterDef {
        needs_repeats: true,
        ..d
    }
}

const fn signed(d: ParameterDef) -> ParameterDef {
    ParameterDef {
        quantity: Quantity::Signed,
        ..d
    }
}

const fn level(d: ParameterDef) -> ParameterDef {
    ParameterDef {
        quantity: Quantity::Level,
        ..d
    }
}

/// ISO 230-2:1997 clause 2 (= GB/T 17421.2-2000, A↓ as corrected by its amendment No. 1).
pub mod iso230_2 {
    use super::*;
    pub static A: ParameterDef = made_of(
        Spread::Band,
        with_role(
            repeated(def(
                ParamKey::A,
                "A",
                "bidirectional accuracy of positioning",
                "ISO 230-2 2.23",
                ISO,
            )),
            Role::Accuracy,
        ),
    );
    pub static A_UP: ParameterDef = made_of(
        Spread::Band,
        only(
            Approach::Up,
            repeated(def(
                ParamKey::AUp,
                "A↑",
                "unidirectional accuracy of positioning ↑",
                "ISO 230-2 2.22",
                ISO,
            )),
        ),
    );
    pub static A_DOWN: ParameterDef = made_of(
        Spread::Band,
        only(
            Approach::Down,
            repeated(def(
                ParamKey::ADown,
                "A↓",
                "unidirectional accuracy of positioning ↓",
                "ISO 230-2 2.22 (GB/T 17421.2 amendment No. 1)",
                ISO,
            )),
        ),
    );
    pub static E: ParameterDef = made_of(
        Spread::Mean,
        with_role(
            def(
                ParamKey::E,
                "E",
                "bidirectional systematic positional deviation",
                "ISO 230-2 2.20",
                ISO,
            ),
            Role::Systematic,
        ),
    );
    pub static E_UP: ParameterDef = made_of(
        Spread::Mean,
        only(
            Approach::Up,
            def(
                ParamKey::EUp,
                "E↑",
                "unidirectional systematic positional deviation ↑",
                "ISO 230-2 2.19",
                ISO,
            ),
        ),
    );
    pub static E_DOWN: ParameterDef = made_of(
        Spread::Mean,
        only(
            Approach::Down,
            def(
                ParamKey::EDown,
                "E↓",
                "unidirectional systematic positional deviation ↓",
                "ISO 230-2 2.19",
                ISO,
            ),
        ),
    );
    pub static M: ParameterDef = made_of(
        Spread::Bidirectional,
        with_role(
            def(
                ParamKey::M,
                "M",
                "range of the mean bidirectional positional deviation",
                "ISO 230-2 2.21",
                ISO,
            ),
            Role::MeanRange,
        ),
    );
    pub static R: ParameterDef = made_of(
        Spread::Repeatability,
        with_role(
            repeated(def(
                ParamKey::R,
                "R",
                "bidirectional repeatability of positioning",
                "ISO 230-2 2.18 (2.17)",
                ISO,
            )),
            Role::Repeatability,
        ),
    );
    pub static R_UP: ParameterDef = made_of(
        Spread::Repeatability,
        only(
            Approach::Up,
            repeated(def(
                ParamKey::RUp,
                "R↑",
                "unidirectional repeatability of positioning ↑",
                "ISO 230-2 2.18 (2.16)",
                ISO,
            )),
        ),
    );
    pub static R_DOWN: ParameterDef = made_of(
        Spread::Repeatability,
        only(
            Approach::Down,
            repeated(def(
                ParamKey::RDown,
                "R↓",
                "unidirectional repeatability of positioning ↓",
                "ISO 230-2 2.18 (2.16)",
                ISO,
            )),
        ),
    );
    pub static B: ParameterDef = made_of(
        Spread::ReversalAtTarget,
        with_role(
            def(
                ParamKey::B,
                "B",
                "reversal value of the axis",
                "ISO 230-2 2.13",
                ISO,
            ),
            Role::Reversal,
        ),
    );
    pub static B_MEAN: ParameterDef = made_of(
        Spread::ReversalMean,
        signed(def(
            ParamKey::BMean,
            "B̄",
            "mean reversal value of the axis",
            "ISO 230-2 2.14",
            ISO,
        )),
    );
}

/// GOST 27843-88 clause 1 (coverage 3S).
pub mod gost27843 {
    use super::*;
    pub static A: ParameterDef = made_of(
        Spread::Band,
        with_role(
            repeated(def(
                ParamKey::A,
                "A",
                "bidirectional positioning accuracy",
                "GOST 27843 1.14 (10)",
                GOST,
            )),
            Role::Accuracy,
        ),
    );
    pub static A_UP: ParameterDef = made_of(
        Spread::Band,
        only(
            Approach::Up,
            repeated(def(
                ParamKey::AUp,
                "A↑",
                "unidirectional positioning accuracy ↑",
                "GOST 27843 1.14 (10)",
                GOST,
            )),
        ),
    );
    pub static A_DOWN: ParameterDef = made_of(
        Spread::Band,
        only(
            Approach::Down,
            repeated(def(
                ParamKey::ADown,
                "A↓",
                "unidirectional positioning accuracy ↓",
                "GOST 27843 1.14 (10)",
                GOST,
            )),
        ),
    );
    pub static R_MAX: ParameterDef = made_of(
        Spread::Repeatability,
        with_role(
            repeated(def(
                ParamKey::RMax,
                "R_max",
                "bidirectional positioning repeatability",
                "GOST 27843 1.11, 1.13 (8)",
                GOST,
            )),
            Role::Repeatability,
        ),
    );
    pub static R_UP: ParameterDef = made_of(
        Spread::Repeatability,
        only(
            Approach::Up,
            repeated(def(
                ParamKey::RUp,
                "R↑",
                "unidirectional positioning repeatability ↑",
                "GOST 27843 1.10, 1.13 (7)",
                GOST,
            )),
        ),
    );
    pub static R_DOWN: ParameterDef = made_of(
        Spread::Repeatability,
        only(
            Approach::Down,
            repeated(def(
                ParamKey::RDown,
                "R↓",
                "unidirectional positioning repeatability ↓",
                "GOST 27843 1.10, 1.13 (7)",
                GOST,
            )),
        ),
    );
    pub static R_MEAN: ParameterDef = made_of(
        Spread::MeanRepeatability,
        repeated(def(
            ParamKey::RMean,
            "R̄",
            "mean bidirectional positioning repeatability",
            "GOST 27843 1.12 (9)",
            GOST,
        )),
    );
    pub static B_MAX: ParameterDef = made_of(
        Spread::ReversalAtTarget,
        with_role(
            def(
                ParamKey::BMax,
                "B_max",
                "maximum dead band (reversal)",
                "GOST 27843 1.16",
                GOST,
            ),
            Role::Reversal,
        ),
    );
    pub static B_MEAN: ParameterDef = made_of(
        Spread::ReversalMean,
        signed(def(
            ParamKey::BMean,
            "B̄",
            "mean dead band (reversal)",
            "GOST 27843 1.15",
            GOST,
        )),
    );
}

/// VDI 3441 as Hemingray, Cowley and Burdekin (1971) describe it, §3.2.
pub mod vdi3441 {
    use super::*;
    const CLAUSE: &str = "VDI 3441 (Hemingray et al. 1971, 3.2)";
    pub static X_MAX: ParameterDef = level(def(
        ParamKey::XMax,
        "X̄max",
        "largest mean deviation",
        CLAUSE,
        VDI,
    ));
    pub static X_MIN: ParameterDef = level(def(
        ParamKey::XMin,
        "X̄min",
        "smallest mean deviation",
        CLAUSE,
        VDI,
    ));
    pub static A_MEAN: ParameterDef = level(def(
        ParamKey::AMean,
        "Ā",
        "mean position deviation (X̄max + X̄min)/2",
        CLAUSE,
        VDI,
    ));
    pub static SIGMA_MEAN: ParameterDef = made_of(
        Spread::Scatter {
            factor: 1.0,
            of_k: false,
        },
        repeated(def(
            ParamKey::SigmaMean,
            "σ̄",
            "mean standard deviation from ranges, σi = Ri/d",
            CLAUSE,
            VDI,
        )),
    );
    pub static G_UPPER: ParameterDef = level(repeated(def(
        ParamKey::GUpper,
        "G_o",
        "upper limit Ā + ((X̄max − X̄min)/2 + 3σ)",
        CLAUSE,
        VDI,
    )));
    pub static G_LOWER: ParameterDef = level(repeated(def(
        ParamKey::GLower,
        "G_u",
        "lower limit Ā − ((X̄max − X̄min)/2 + 3σ)",
        CLAUSE,
        VDI,
    )));
    pub static T: ParameterDef = repeated(def(
        ParamKey::T,
        "T_E",
        "position error X̄max − X̄min + 6σ",
        CLAUSE,
        VDI,
    ));
    pub static R_P: ParameterDef = made_of(
        Spread::Scatter {
            factor: 2.0,
            of_k: true,
        },
        repeated(def(
            ParamKey::Rp,
            "R_p",
            "position scatter width 6σ",
            CLAUSE,
            VDI,
        )),
    );
}

/// The NMTBA accuracy definition as Hemingray, Cowley and Burdekin (1971) describe it, §3.1.
pub mod nmtba {
    use super::*;
    const CLAUSE: &str = "NMTBA (Hemingray et al. 1971, 3.1)";
    pub static A: ParameterDef = with_role(
        repeated(def(
            ParamKey::A,
            "A_b",
            "bidirectional accuracy max(|X̄i − zero| + 3σi)",
            CLAUSE,
            NMTBA,
        )),
        Role::Accuracy,
    );
    pub static A_UP: ParameterDef = only(
        Approach::Up,
        repeated(def(
            ParamKey::AUp,
            "A_u↑",
            "unidirectional accuracy ↑",
            CLAUSE,
            NMTBA,
        )),
    );
    pub static A_DOWN: ParameterDef = only(
        Approach::Down,
        repeated(def(
            ParamKey::ADown,
            "A_u↓",
            "unidirectional accuracy ↓",
            CLAUSE,
            NMTBA,
        )),
    );
    pub static ZERO: ParameterDef = level(repeated(def(
        ParamKey::Zero,
        "zero",
        "zero line, midway between the extreme means",
        CLAUSE,
        NMTBA,
    )));
    pub static SPREAD: ParameterDef = made_of(
        Spread::Scatter {
            factor: 1.0,
            of_k: true,
        },
        repeated(def(
            ParamKey::Spread,
            "3σ_b",
            "largest bidirectional scatter 3σ",
            CLAUSE,
            NMTBA,
        )),
    );
    pub static SPREAD_UP: ParameterDef = made_of(
        Spread::Scatter {
            factor: 1.0,
            of_k: true,
        },
        only(
            Approach::Up,
            repeated(def(
                ParamKey::SpreadUp,
                "3σ_u↑",
                "largest unidirectional scatter 3σ",
                CLAUSE,
                NMTBA,
            )),
        ),
    );
    pub static SPREAD_DOWN: ParameterDef = made_of(
        Spread::Scatter {
            factor: 1.0,
            of_k: true,
        },
        only(
            Approach::Down,
            repeated(def(
                ParamKey::SpreadDown,
                "3σ_u↓",
                "largest unidirectional scatter 3σ",
                CLAUSE,
                NMTBA,
            )),
        ),
    );
    pub static L_MAX: ParameterDef = made_of(
        Spread::LostMotion,
        def(
            ParamKey::LMax,
            "L_max",
            "largest lost motion |X̄i↑ − X̄i↓|",
            CLAUSE,
            NMTBA,
        ),
    );
    pub static L_MEAN: ParameterDef = made_of(
        Spread::LostMotion,
        signed(def(ParamKey::LMean, "L̄", "mean lost motion", CLAUSE, NMTBA)),
    );
}

/// Every definition, each standard's in the order the standard lists them.
pub static CATALOGUE: &[&ParameterDef] = &[
    &iso230_2::A,
    &iso230_2::A_UP,
    &iso230_2::A_DOWN,
    &iso230_2::E,
    &iso230_2::E_UP,
    &iso230_2::E_DOWN,
    &iso230_2::M,
    &iso230_2::R,
    &iso230_2::R_UP,
    &iso230_2::R_DOWN,
    &iso230_2::B,
    &iso230_2::B_MEAN,
    &gost27843::A,
    &gost27843::A_UP,
    &gost27843::A_DOWN,
    &gost27843::R_MAX,
    &gost27843::R_UP,
    &gost27843::R_DOWN,
    &gost27843::R_MEAN,
    &gost27843::B_MAX,
    &gost27843::B_MEAN,
    &vdi3441::X_MAX,
    &vdi3441::X_MIN,
    &vdi3441::A_MEAN,
    &vdi3441::SIGMA_MEAN,
    &vdi3441::G_UPPER,
    &vdi3441::G_LOWER,
    &vdi3441::T,
    &vdi3441::R_P,
    &nmtba::A,
    &nmtba::A_UP,
    &nmtba::A_DOWN,
    &nmtba::ZERO,
    &nmtba::SPREAD,
    &nmtba::SPREAD_UP,
    &nmtba::SPREAD_DOWN,
    &nmtba::L_MAX,
    &nmtba::L_MEAN,
];

/// The parameters of `standard`, in its order.
pub fn of(standard: StandardId) -> impl Iterator<Item = &'static ParameterDef> {
    CATALOGUE
        .iter()
        .copied()
        .filter(move |d| d.defined_by(standard))
}

/// `standard`'s definition of `key`.
pub fn find(standard: StandardId, key: &str) -> Option<&'static ParameterDef> {
    of(standard).find(|d| d.key.as_str() == key)
}

/// The distinct keys of the definitions `keep` selects, in catalogue order.
fn keys_where(keep: impl Fn(&ParameterDef) -> bool) -> Vec<ParamKey> {
    let mut keys: Vec<ParamKey> = Vec::new();
    for d in CATALOGUE.iter().filter(|d| keep(d)) {
        if !keys.contains(&d.key) {
            keys.push(d.key);
        }
    }
    keys
}

/// Every key a tolerance limit may name, whatever the standard.
pub fn limitable_keys() -> &'static [&'static str] {
    static KEYS: LazyLock<Vec<&'static str>> = LazyLock::new(|| {
        (keys_where(ParameterDef::limitable).into_iter())
            .map(ParamKey::as_str)
            .collect()
    });
    &KEYS
}

/// The key `text` writes, if a tolerance limit may name it.
pub fn limitable(text: &str) -> Option<ParamKey> {
    ParamKey::parse(text).filter(|&k| CATALOGUE.iter().any(|d| d.key == k && d.limitable()))
}

/// The keys of ISO 230-2's and GOST 27843's parameters: the parameter columns of the
/// summary table (a stable interface: VDI 3441 and NMTBA values are in `results.json`).
pub fn summary_keys() -> &'static [ParamKey] {
    static KEYS: LazyLock<Vec<ParamKey>> = LazyLock::new(|| {
        keys_where(|d| d.defined_by(StandardId::Iso230_2) || d.defined_by(StandardId::Gost27843))
    });
    &KEYS
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_unique_within_each_standard() {
        for standard in StandardId::ALL {
            let keys: Vec<&str> = of(standard).map(|d| d.key.as_str()).collect();
            let mut unique = keys.clone();
            unique.sort_unstable();
            unique.dedup();
            assert_eq!(keys.len(), unique.len(), "{standard}: {keys:?}");
            assert!(!keys.is_empty(), "{standard}");
        }
    }

    #[test]
    fn summary_columns_are_the_iso_and_gost_keys() {
        let keys: Vec<&str> = summary_keys().iter().map(|k| k.as_str()).collect();
        assert_eq!(
            keys,
            [
                "A", "A_up", "A_down", "E", "E_up", "E_down", "M", "R", "R_up", "R_down", "B",
                "B_mean", "R_max", "R_mean", "B_max"
            ]
        );
    }

    #[test]
    fn levels_take_no_limit() {
        let keys = limitable_keys();
        for k in ["X_max", "X_min", "A_mean", "G_upper", "G_lower", "zero"] {
            assert!(!keys.contains(&k), "{k}");
        }
        for k in [
            "A",
            "B_mean",
            "T",
            "R_p",
            "sigma_mean",
            "spread",
            "L_max",
            "L_mean",
        ] {
            assert!(keys.contains(&k), "{k}");
        }
        assert_eq!(keys.len(), 23);
    }

    /// Every key names an entry, in the order the catalogue first lists it.
    #[test]
    fn the_keys_are_the_catalogues() {
        assert_eq!(ParamKey::ALL.to_vec(), keys_where(|_| true));
    }

    #[test]
    fn a_limit_may_name_the_limitable_keys_only() {
        for text in ParamKey::ALL
            .map(ParamKey::as_str)
            .into_iter()
            .chain(["AA", "a", ""])
        {
            let limitable = limitable(text);
            assert_eq!(
                limitable.is_some(),
                limitable_keys().contains(&text),
                "{text}"
            );
            assert!(limitable.is_none_or(|k| k.as_str() == text));
        }
    }

    #[test]
    fn approach_matches_the_arrow() {
        for d in CATALOGUE {
            let key = d.key.as_str();
            let want = match (key.ends_with("_up"), key.ends_with("_down")) {
                (true, _) => Approach::Up,
                (_, true) => Approach::Down,
                _ => Approach::Both,
            };
            assert_eq!(d.approach, want, "{}", d.key);
            assert_eq!(
                d.approach == Approach::Up,
                d.symbol.contains('↑'),
                "{}",
                d.key
            );
        }
    }

    /// The scatter parameters of each standard are those the compensation report named
    /// by key (`R_up`, `R_down`, `sigma_mean`, `spread_up`, `spread_down`) before the
    /// catalogue said it.
    #[test]
    fn scatter_parameters_are_the_listed_ones() {
        let listed = ["R_up", "R_down", "sigma_mean", "spread_up", "spread_down"];
        for standard in StandardId::ALL {
            let scatter: Vec<&str> = of(standard)
                .filter(|d| d.is_scatter())
                .map(|d| d.key.as_str())
                .collect();
            let by_key: Vec<&str> = of(standard)
                .map(|d| d.key.as_str())
                .filter(|k| listed.contains(k))
                .collect();
            assert_eq!(scatter, by_key, "{standard}");
            let want: &[&str] = match standard {
                StandardId::Iso230_2 | StandardId::Gbt17421_2 | StandardId::Gost27843 => {
                    &["R_up", "R_down"]
                }
                StandardId::Vdi3441 => &["sigma_mean"],
                StandardId::Nmtba => &["spread_up", "spread_down"],
            };
            assert_eq!(scatter, want, "{standard}");
        }
    }

    #[test]
    fn one_headline_per_role_and_standard() {
        for standard in StandardId::ALL {
            for role in [
                Role::Accuracy,
                Role::Systematic,
                Role::MeanRange,
                Role::Repeatability,
                Role::Reversal,
            ] {
                assert!(of(standard).filter(|d| d.role == Some(role)).count() <= 1);
            }
        }
    }
}
