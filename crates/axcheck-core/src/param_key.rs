//! A parameter's stable key as a type, so that what names a parameter after a file is
//! read (a tolerance limit, a catalogue entry) is checked once, at the file's edge.

use serde::{Serialize, Serializer};
use std::cmp::Ordering;
use std::fmt;

/// A key of the [`crate::evaluate::catalogue`], as JSON, specs, tolerances and table columns write
/// it ([`ParamKey::as_str`]). One key may name a parameter of several standards (ISO
/// 230-2's and NMTBA's `A`): the catalogue's entries say what it is in each.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ParamKey {
    A,
    AUp,
    ADown,
    E,
    EUp,
    EDown,
    M,
    R,
    RUp,
    RDown,
    B,
    BMean,
    RMax,
    RMean,
    BMax,
    XMax,
    XMin,
    AMean,
    SigmaMean,
    GUpper,
    GLower,
    T,
    Rp,
    Zero,
    Spread,
    SpreadUp,
    SpreadDown,
    LMax,
    LMean,
    /// The other laser tests' values (ISO 230-1), judged like the parameters: a
    /// straightness (µm), a local straightness over a stated length (µm), an angular
    /// deviation (arcsec).
    Straightness,
    StraightnessLocal,
    Angular,
    /// The squareness of two axes, arcsec.
    Squareness,
}

impl ParamKey {
    /// Every positioning parameter's key, in the order the catalogue first lists it.
    pub const ALL: [ParamKey; 29] = {
        use ParamKey::*;
        [
            A, AUp, ADown, E, EUp, EDown, M, R, RUp, RDown, B, BMean, RMax, RMean, BMax, XMax,
            XMin, AMean, SigmaMean, GUpper, GLower, T, Rp, Zero, Spread, SpreadUp, SpreadDown,
            LMax, LMean,
        ]
    };

    /// The keys of the other laser tests' values (not in the positioning catalogue: no
    /// positioning tolerance may name them).
    pub const GEOMETRY: [ParamKey; 4] = [
        ParamKey::Straightness,
        ParamKey::StraightnessLocal,
        ParamKey::Angular,
        ParamKey::Squareness,
    ];

    /// The key as files and outputs write it: `A`, `A_up`, `R_max` …
    pub fn as_str(self) -> &'static str {
        use ParamKey::*;
        match self {
            A => "A",
            AUp => "A_up",
            ADown => "A_down",
            E => "E",
            EUp => "E_up",
            EDown => "E_down",
            M => "M",
            R => "R",
            RUp => "R_up",
            RDown => "R_down",
            B => "B",
            BMean => "B_mean",
            RMax => "R_max",
            RMean => "R_mean",
            BMax => "B_max",
            XMax => "X_max",
            XMin => "X_min",
            AMean => "A_mean",
            SigmaMean => "sigma_mean",
            GUpper => "G_upper",
            GLower => "G_lower",
            T => "T",
            Rp => "R_p",
            Zero => "zero",
            Spread => "spread",
            SpreadUp => "spread_up",
            SpreadDown => "spread_down",
            LMax => "L_max",
            LMean => "L_mean",
            Straightness => "straightness",
            StraightnessLocal => "straightness_local",
            Angular => "angular",
            Squareness => "squareness",
        }
    }

    /// The key `text` writes, if it is one (spelled exactly: keys are case-sensitive).
    pub fn parse(text: &str) -> Option<ParamKey> {
        (ParamKey::ALL.into_iter().chain(ParamKey::GEOMETRY)).find(|k| k.as_str() == text)
    }
}

/// Ordered as the keys are written (byte order), so that a map keyed by `ParamKey` lists
/// them as the string-keyed maps it replaced did: outputs that walk tolerance limits keep
/// their order.
impl Ord for ParamKey {
    fn cmp(&self, other: &ParamKey) -> Ordering {
        self.as_str().cmp(other.as_str())
    }
}

impl PartialOrd for ParamKey {
    fn partial_cmp(&self, other: &ParamKey) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Display for ParamKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// Written as its key, as the string it replaced was.
impl Serialize for ParamKey {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.as_str())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    #[test]
    fn every_key_reads_back_and_is_distinct() {
        let every = || ParamKey::ALL.into_iter().chain(ParamKey::GEOMETRY);
        for k in every() {
            assert_eq!(ParamKey::parse(k.as_str()), Some(k));
        }
        let mut written: Vec<&str> = every().map(|k| k.as_str()).collect();
        written.sort_unstable();
        written.dedup();
        assert_eq!(written.len(), every().count());
        assert_eq!(ParamKey::parse("a"), None);
        assert_eq!(ParamKey::parse("A "), None);
    }

    /// A map keyed by `ParamKey` walks and serialises its keys as one keyed by the strings.
    #[test]
    fn maps_keep_the_order_of_the_strings() {
        let typed: BTreeMap<ParamKey, usize> = ParamKey::ALL.into_iter().zip(0..).collect();
        let strings: BTreeMap<&str, usize> = ParamKey::ALL
            .into_iter()
            .map(ParamKey::as_str)
            .zip(0..)
            .collect();
        let typed_keys: Vec<&str> = typed.keys().map(|k| k.as_str()).collect();
        assert_eq!(typed_keys, strings.keys().copied().collect::<Vec<_>>());
        assert_eq!(
            serde_json::to_string(&typed).unwrap(),
            serde_json::to_string(&strings).unwrap()
        );
    }
}
