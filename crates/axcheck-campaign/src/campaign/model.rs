//! The campaign file's types. Core keys are fixed (scripts write them); everything a
//! test report needs by ISO 230-2 clause 7.1 has a key of its own.

use super::report_options::ReportOptions;
use crate::axis_model::Cycle;
use crate::geometry::TestKind;
use crate::geometry::line::ReferenceLine;
use crate::geometry::optics::Optics;
use crate::geometry::squareness::Convention;
use crate::geometry::tolerance::Tolerance;
use crate::judge::{DecisionRule, Tolerances};
use crate::uncertainty::InstrumentKind;
use crate::units::{AxisKind, Travel};
use crate::yaml::describe;
use serde::de::{Deserializer, Error as _, IgnoredAny};
use serde::{Deserialize, Serialize};
use serde_norway::Value;
use std::collections::BTreeMap;

/// The `campaign:` block.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CampaignInfo {
    pub name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub site: Option<String>,
    /// `periodic`, `acceptance`, `comparison`, `type`, `compensation` … (ISO 230-2 clause 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub purpose: Option<String>,
    /// Test date, YYYY-MM-DD; also the date printed in reports.
    #[serde(
        default,
        deserialize_with = "super::dates::iso_date",
        skip_serializing_if = "Option::is_none"
    )]
    pub date: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inspector: Option<String>,
    /// Default standard for every axis (`iso230-2` when absent).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub standard: Option<String>,
    /// Default acceptance spec for every axis.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spec: Option<String>,
    /// Default decision rule for every axis (`simple` when absent; ISO 14253-1).
    #[serde(
        default,
        deserialize_with = "crate::yaml::optional_keyword",
        skip_serializing_if = "Option::is_none"
    )]
    pub decision_rule: Option<DecisionRule>,
    /// Whether a test judged against no limit (`not_judged`) may pass the gate:
    /// `unjudged: allowed` lets `check` and `run` exit 0 on it (the count is still shown);
    /// absent or `refused`, such a test makes them exit 1.
    #[serde(
        default,
        deserialize_with = "crate::yaml::optional_keyword",
        skip_serializing_if = "Option::is_none"
    )]
    pub unjudged: Option<Unjudged>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// Allow data paths that are absolute or leave the campaign's folder.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub allow_outside_paths: bool,
    /// Folder of the inspection history `run` appends to (relative to the campaign file,
    /// under the same path rule as data files); `--history` overrides it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub history: Option<String>,
    /// Years after the latest inspection within which `run` flags a forecast crossing of
    /// a limit (as `trend --horizon`; 2 when absent); `--horizon` overrides it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trend_horizon_years: Option<f64>,
    #[serde(default)]
    pub output: OutputOptions,
    /// The campaign's reports are a laboratory's calibration certificate (ISO/IEC 17025).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub certificate: Option<super::certificate::CertificateRaw>,
    /// `report: {lang: zh}`: the reports' language (`report_options::report_lang`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub report: Option<ReportOptions>,
}

/// `campaign.unjudged`: what the gate makes of a test no limit was applied to.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Unjudged {
    /// Such a test fails the gate (exit 1): a CI job is not green because a key is missing.
    #[default]
    Refused,
    /// Such a test is counted apart and does not fail the gate.
    Allowed,
}

impl CampaignInfo {
    /// Whether tests without limits may pass the gate (`unjudged: allowed`).
    pub fn unjudged_allowed(&self) -> bool {
        self.unjudged == Some(Unjudged::Allowed)
    }
}

/// `campaign.output`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OutputOptions {
    /// Write PDF reports in `run`.
    pub pdf: bool,
    /// Model check and diagnosis of every axis.
    pub diagnose: bool,
    /// Write `summary.html` in `run`.
    pub html: bool,
}

impl Default for OutputOptions {
    fn default() -> Self {
        OutputOptions {
            pdf: true,
            diagnose: true,
            html: true,
        }
    }
}

/// A machine (clause 7.1: model, name, type, axis travels).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MachineInfo {
    pub id: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub model: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub serial: Option<String>,
    /// E.g. "vertical machining centre".
    #[serde(rename = "type", default, skip_serializing_if = "Option::is_none")]
    pub machine_type: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub location: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub notes: Option<String>,
    /// The controller whose compensation table `run` writes for each axis
    /// (`compensation/MACHINE/AXIS.<ext>`), e.g. `csv`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub controller: Option<String>,
    /// This machine's reports are a laboratory's calibration certificate (in place of the
    /// campaign's `certificate`, if any).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub certificate: Option<super::certificate::CertificateRaw>,
    /// `report: {lang: ru}`: this machine's reports' language.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub report: Option<ReportOptions>,
    /// Lets `axes` through the unknown-key check: the loader reads the axes one by one
    /// from the document, so that a broken axis fails alone.
    #[serde(default, skip_serializing)]
    pub axes: IgnoredAny,
    /// Squareness of pairs of the machine's linear axes from their straightness tests
    /// (read one by one by the loader, as the axes).
    #[serde(default, skip_serializing)]
    pub squareness: IgnoredAny,
}

/// A squareness of two linear axes from their straightness tests in the campaign and an
/// optical square (ISO 230-1; the method and sign of the HP 5528A User's Guide, §21):
/// `axes: [X, Y]` takes the straightness of X along Y (EYX) and of Y along X (EXY).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SquarenessRaw {
    pub axes: [String; 2],
    /// The optical square's error as printed on it, arcsec (0 when absent).
    #[serde(default)]
    pub square_error_arcsec: f64,
    /// The standard uncertainty of that error (its calibration), arcsec.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub square_u_arcsec: Option<f64>,
    /// The sign: `over_90` (positive when the angle is larger than 90°, the default) or
    /// `under_90`.
    #[serde(
        default,
        deserialize_with = "crate::yaml::optional_keyword",
        skip_serializing_if = "Option::is_none"
    )]
    pub convention: Option<Convention>,
    /// The reference lines, `least_squares` (default) or `end_point`.
    #[serde(
        default,
        deserialize_with = "crate::yaml::optional_keyword",
        skip_serializing_if = "Option::is_none"
    )]
    pub line: Option<ReferenceLine>,
    /// As an axis's: `20″`, or a slope `0.020 per 1000`; checked by the loader.
    #[serde(
        rename = "tolerance",
        default,
        deserialize_with = "one_or_many_texts",
        skip_serializing
    )]
    pub(super) written_tolerance: Vec<String>,
    #[serde(skip_deserializing, skip_serializing_if = "Vec::is_empty")]
    pub tolerance: Vec<(String, Tolerance)>,
    /// The optics' accuracy for U, as an axis entry's `optics:` (arcsec): checked by the
    /// loader.
    #[serde(rename = "optics", default, skip_serializing)]
    pub(super) written_optics: Option<Value>,
    #[serde(skip_deserializing, skip_serializing_if = "Option::is_none")]
    pub optics: Option<Optics>,
}

/// An axis as written in the campaign.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AxisRaw {
    pub name: String,
    #[serde(deserialize_with = "crate::yaml::keyword")]
    pub kind: AxisKind,
    /// Axis travel (clause 2.1), mm or deg.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub travel: Option<Travel>,
    /// A rotary axis that turns freely (a table with no end stops): planned over its whole
    /// travel with overruns beyond its ends; any other axis keeps every move inside it.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub continuous: bool,
    /// Measurement travel (clause 2.2), [first, last], mm or deg.
    #[serde(
        default,
        deserialize_with = "first_last",
        skip_serializing_if = "Option::is_none"
    )]
    pub measurement_travel: Option<[f64; 2]>,
    /// One file, a list, or `{dir, glob}`.
    pub data: serde_norway::Value,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub standard: Option<String>,
    /// Acceptance spec (overrides the campaign's); `none` for no spec.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spec: Option<String>,
    /// The limits as the file writes them: read by serde, then checked and moved into
    /// `tolerances` by the loader (empty after it).
    #[serde(rename = "tolerances", default, skip_serializing)]
    pub(super) written_tolerances: BTreeMap<String, f64>,
    /// Per-parameter limits, µm (linear) or arcsec (rotary), overriding the spec.
    #[serde(skip_deserializing, skip_serializing_if = "BTreeMap::is_empty")]
    pub tolerances: Tolerances,
    /// Decision rule of this axis: overrides its spec's and the campaign's.
    #[serde(
        default,
        deserialize_with = "crate::yaml::optional_keyword",
        skip_serializing_if = "Option::is_none"
    )]
    pub decision_rule: Option<DecisionRule>,
    /// Lead-screw or encoder pitch, mm or deg.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pitch: Option<f64>,
    /// Where a thermal growth of the axis holds still (the lead screw's fixed bearing),
    /// mm or deg: the diagnosis then tells a drift from a growth about another origin.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thermal_origin: Option<f64>,
    /// GOST 27843 only: S from ranges, formula (6).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub s_from_ranges: bool,
    /// The compensation table's grid, when the machine names a controller.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compensation: Option<Box<CompensationRaw>>,
    /// The test planned for the axis (`axcheck plan -o`): its measurement is compared with
    /// it. `plan: FILE` or `plan: {file: FILE, tolerance: 0.01}`.
    #[serde(
        default,
        deserialize_with = "plan_ref",
        skip_serializing_if = "Option::is_none"
    )]
    pub plan: Option<PlanRaw>,
    #[serde(default)]
    pub conditions: Box<Conditions>,
    /// The other laser tests of a linear axis (ISO 230-1): which test the files hold
    /// and how it is evaluated and judged. `test: straightness` with `direction: Y` is
    /// EYX of an X axis, `test: angular` with `about: B` its pitch EBX. `positioning`
    /// (ISO 230-2) when absent.
    #[serde(
        default,
        deserialize_with = "crate::yaml::keyword",
        skip_serializing_if = "is_positioning"
    )]
    pub test: TestKind,
    /// Straightness: the axis the deviation is along (`Y` or `Z` for an X axis).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub direction: Option<char>,
    /// Angular: the axis the rotation is about (`A` roll, `B` pitch, `C` yaw of an X
    /// axis; ISO 230-1 names them by the axis of rotation).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub about: Option<char>,
    /// Straightness: the reference line, `least_squares` (default) or `end_point`.
    #[serde(
        default,
        deserialize_with = "crate::yaml::optional_keyword",
        skip_serializing_if = "Option::is_none"
    )]
    pub line: Option<ReferenceLine>,
    /// Straightness: the local straightness over any stretch of this length, mm (taken
    /// from a tolerance `… over any L` when absent).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub local_mm: Option<f64>,
    /// The test's tolerances as written (`0.020 per 1000`, `0.010 over any 300`, `30″`):
    /// read by serde, then checked and moved into `tolerance` by the loader.
    #[serde(
        rename = "tolerance",
        default,
        deserialize_with = "one_or_many_texts",
        skip_serializing
    )]
    pub(super) written_tolerance: Vec<String>,
    /// The tolerances, each beside its text.
    #[serde(skip_deserializing, skip_serializing_if = "Vec::is_empty")]
    pub tolerance: Vec<(String, Tolerance)>,
    /// Straightness or angular: the optics' accuracy for U, a preset's name or `{percent:
    /// 0.5, fixed: 0.5, per_m: 0, per_m2: 0.15}` in the result's unit (µm or arcsec): read
    /// by serde, then checked and moved into `optics` by the loader.
    #[serde(rename = "optics", default, skip_serializing)]
    pub(super) written_optics: Option<Value>,
    /// The optics as stated.
    #[serde(skip_deserializing, skip_serializing_if = "Option::is_none")]
    pub optics: Option<Optics>,
    /// Positioning: where the tool point is from the laser beam, mm (`{y_mm: 0, z_mm:
    /// 150}` for an X axis whose beam runs 150 mm below it): the test is also carried to
    /// it through the axis's angular tests in the campaign (Abbe, `geometry::abbe`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tool_point: Option<ToolPointRaw>,
}

/// An optics' accuracy stated as numbers (`optics: {percent: 0.5, fixed: 0.5}`): ±(percent %
/// of the value + fixed + per_m·M + per_m2·M²), M the travel in m, in the result's unit.
#[derive(Debug, Clone, Copy, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OpticsStatedRaw {
    #[serde(default)]
    pub percent: Option<f64>,
    #[serde(default)]
    pub fixed: Option<f64>,
    #[serde(default)]
    pub per_m: Option<f64>,
    #[serde(default)]
    pub per_m2: Option<f64>,
}

/// The tool point's offsets from the beam across the axis, mm (the axis's own left out).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ToolPointRaw {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub x_mm: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub y_mm: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub z_mm: Option<f64>,
}

impl ToolPointRaw {
    /// The offset along `letter` (`X`, `Y`, `Z`), 0 when not given.
    pub fn along(&self, letter: char) -> f64 {
        match letter {
            'X' => self.x_mm,
            'Y' => self.y_mm,
            _ => self.z_mm,
        }
        .unwrap_or(0.0)
    }
}

fn is_positioning(test: &TestKind) -> bool {
    *test == TestKind::Positioning
}

/// A tolerance or a list of them: text (`0.020 per 1000`) or a number (mm).
fn one_or_many_texts<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Vec<String>, D::Error> {
    let text = |v: &Value| match v {
        Value::String(s) => Ok(s.clone()),
        Value::Number(n) => Ok(n.to_string()),
        other => Err(D::Error::custom(format!(
            "expected a tolerance such as `0.020 per 1000` or `30″`, got {}",
            describe(other)
        ))),
    };
    match Value::deserialize(deserializer)? {
        Value::Null => Ok(Vec::new()),
        Value::Mapping(_) => Err(D::Error::custom(
            "limits by parameter are `tolerances: {A: …}` (did you mean `tolerances`?); `tolerance:` is a straightness, angular or squareness test's, e.g. `0.020 per 1000`",
        )),
        Value::Sequence(items) => items.iter().map(text).collect(),
        one => Ok(vec![text(&one)?]),
    }
}

/// An axis's compensation table: `compensation: {interval: 50, reference: 0, axis: X1}`
/// (mm or deg).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CompensationRaw {
    /// The axis's name on the controller, where the file names it (HEIDENHAIN `X`, Siemens
    /// `X1`, TwinCAT its logical number `2`); default: a placeholder in the file that the
    /// control cannot load.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis: Option<String>,
    /// A straightness test's cross table: the axis measured along (its input) and the
    /// axis corrected (its output), as the controller names them; default: the axis's
    /// name and the straightness's `direction`, as the campaign names them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub input: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub output: Option<String>,
    /// Spacing of an equidistant table; default: the controller's (the targets, or their
    /// mean spacing).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub interval: Option<f64>,
    /// The reference point: the grid passes through it and the correction is zero there.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reference: Option<f64>,
    /// Siemens: the measuring system the table is for, 0 (the first encoder, default) or 1
    /// (a direct measuring system the axis is closed on).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub measuring_system: Option<u8>,
    /// LinuxCNC: the file's `COMP_FILE_TYPE`, 0 (actual positions, LinuxCNC's default and
    /// axcheck's) or 1 (trims).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub comp_file_type: Option<u8>,
    /// What was active during this test (ISO 230-2 3.2): `none`, or the table file in the
    /// controller's format and its backlash parameter; absent: not stated (a warning says
    /// so). With `verifies`, the table verified.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub active: Option<ActiveRaw>,
    /// This test re-measures the axis after a table was loaded: the measurement before
    /// and the table, to compare the prediction with this test.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub verifies: Option<VerifiesRaw>,
}

/// A planned test: its file (relative to the campaign, like data files) and how far a
/// measured target may lie from its planned position (mm or deg; default 0.01).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlanRaw {
    pub file: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
}

/// Reads `FILE` or `{file, tolerance}`.
fn plan_ref<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Option<PlanRaw>, D::Error> {
    let value = Value::deserialize(deserializer)?;
    match &value {
        Value::String(s) => Ok(Some(PlanRaw {
            file: s.clone(),
            tolerance: None,
        })),
        Value::Mapping(_) => PlanRaw::deserialize(value)
            .map(Some)
            .map_err(D::Error::custom),
        other => Err(D::Error::custom(format!(
            "expected a plan file or {{file: FILE, tolerance: N}}, got {}",
            describe(other)
        ))),
    }
}

/// What was active during a test: `active: none`, or `active: {file: FILE, backlash_um: N}`
/// (`backlash_arcsec` on a rotary axis).
#[derive(Debug, Clone, PartialEq)]
pub enum ActiveRaw {
    None,
    Stated(ActiveStated),
}

/// A stated active compensation: the controller's table file (relative to the campaign,
/// like data files) and its backlash parameter, µm or arcsec.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ActiveStated {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub backlash_um: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub backlash_arcsec: Option<f64>,
}

/// `verifies: {before: FILE, table: FILE, backlash_um: N, active: …}`: the measurement
/// before the table was loaded, the table (in the controller's format) and the backlash
/// loaded with it, and what was active during the measurement before (default `none`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VerifiesRaw {
    pub before: String,
    pub table: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub backlash_um: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub backlash_arcsec: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub active: Option<ActiveRaw>,
}

impl Serialize for ActiveRaw {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            ActiveRaw::None => serializer.serialize_str("none"),
            ActiveRaw::Stated(s) => s.serialize(serializer),
        }
    }
}

/// Reads `none` or the mapping, and says which two it accepts when given neither.
impl<'de> Deserialize<'de> for ActiveRaw {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<ActiveRaw, D::Error> {
        struct ActiveVisitor;

        impl<'de> serde::de::Visitor<'de> for ActiveVisitor {
            type Value = ActiveRaw;

            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("`none` or {file: TABLE, backlash_um: N}")
            }

            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<ActiveRaw, E> {
                match v {
                    "none" => Ok(ActiveRaw::None),
                    _ => Err(E::invalid_value(serde::de::Unexpected::Str(v), &self)),
                }
            }

            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                map: A,
            ) -> Result<ActiveRaw, A::Error> {
                let stated =
                    ActiveStated::deserialize(serde::de::value::MapAccessDeserializer::new(map))?;
                Ok(ActiveRaw::Stated(stated))
            }
        }

        deserializer.deserialize_any(ActiveVisitor)
    }
}

/// The test conditions clause 7.1 asks the report to state.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Conditions {
    /// Measuring instrument and its position (4.3.1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub instrument: Option<InstrumentEntry>,
    /// Test equipment: maker, model and serial of laser head, optics, sensors.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub equipment: Vec<String>,
    /// Type of positioning element (ball screw and rotary encoder, glass scale, …).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub positioning_element: Option<String>,
    /// Temperature sensors on machine parts and in the air, start and end readings.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub temperature_sensors: Vec<TemperatureSensor>,
    /// Air temperature, pressure and humidity at start and end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub air: Option<Air>,
    /// Nominal differential expansion correction (3.1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub nde: Option<Nde>,
    #[serde(
        default,
        alias = "feed_deg_per_min",
        skip_serializing_if = "Option::is_none"
    )]
    pub feed_mm_per_min: Option<f64>,
    /// Dwell at each target, s.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dwell_s: Option<f64>,
    /// Compensation active during the test (3.2), e.g. "reversal and lead screw" or "none".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compensation: Option<String>,
    /// Positions of the axes not under test (3.2), e.g. "Y = 300 mm, Z = 350 mm".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub other_axes: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tool_offset: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub workpiece_offset: Option<String>,
    /// Warm-up before the test (3.3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub warm_up: Option<String>,
    /// Test cycle: standard, step or pilgrim.
    #[serde(
        default,
        deserialize_with = "crate::yaml::optional_keyword",
        skip_serializing_if = "Option::is_none"
    )]
    pub cycle: Option<Cycle>,
    /// Pressure of air or oil where used (7.1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fluid_pressure: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub notes: Option<String>,
}

#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InstrumentEntry {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// What kind of instrument (it sets the uncertainty budget's defaults); guessed from
    /// `name` when absent.
    #[serde(
        default,
        deserialize_with = "crate::yaml::optional_keyword",
        skip_serializing_if = "Option::is_none"
    )]
    pub kind: Option<InstrumentKind>,
    /// Fixed part of its accuracy ±(fixed + ppm·L), µm (linear) or arcsec (rotary): a
    /// specification's limits, or with `accuracy_k` a calibration certificate's U.
    #[serde(
        default,
        alias = "accuracy_um",
        alias = "accuracy_arcsec",
        skip_serializing_if = "Option::is_none"
    )]
    pub(crate) accuracy_fixed: Option<f64>,
    /// Length-proportional part of its accuracy, ppm of the measured length.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) accuracy_ppm: Option<f64>,
    /// Coverage factor of a certificate's stated U (normal distribution); absent: the
    /// accuracy is a specification's ± limits (rectangular).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub accuracy_k: Option<f64>,
    /// Smallest step of its indication, µm or arcsec.
    #[serde(
        default,
        alias = "resolution_um",
        alias = "resolution_arcsec",
        skip_serializing_if = "Option::is_none"
    )]
    pub resolution: Option<f64>,
    /// Dead path: distance from the interferometer to the reflector at the datum, mm
    /// (0 when the laser's software compensates it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dead_path_mm: Option<f64>,
    /// Lateral walk of the beam on its target over the measurement travel, mm (cosine
    /// error).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) beam_walk_mm: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub serial: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position: Option<String>,
    /// Its calibration: a test after the due date is not traceable
    /// (`instrument-calibration-due`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub calibration: Option<CalibrationEntry>,
}

/// An instrument's calibration as its certificate states it (ISO/IEC 17025:2017 6.4.13 e):
/// the certificate's number, the day it was calibrated, the day the next calibration is
/// due, and the body that calibrated it.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CalibrationEntry {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub certificate: Option<String>,
    #[serde(
        default,
        deserialize_with = "super::dates::iso_date",
        skip_serializing_if = "Option::is_none"
    )]
    pub calibrated_on: Option<String>,
    #[serde(
        default,
        deserialize_with = "super::dates::iso_date",
        skip_serializing_if = "Option::is_none"
    )]
    pub due: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub body: Option<String>,
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SensorKind {
    #[default]
    Material,
    Air,
}

#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TemperatureSensor {
    pub name: String,
    #[serde(default, deserialize_with = "crate::yaml::keyword")]
    pub kind: SensorKind,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end_c: Option<f64>,
}

#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Air {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temperature_start_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temperature_end_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pressure_kpa: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub humidity_pct: Option<f64>,
}

/// NDE correction (clause 3.1).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Nde {
    /// The data are already corrected to 20 °C (by the instrument).
    #[serde(default)]
    pub corrected: bool,
    /// Effective expansion coefficient of the positioning system, µm/(m·°C).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coefficient_um_per_m_c: Option<f64>,
}

/// `[first, last]`: two numbers (their order is checked with the other axis values).
fn first_last<'de, D: Deserializer<'de>>(deserializer: D) -> Result<Option<[f64; 2]>, D::Error> {
    struct FirstLast;

    impl<'de> serde::de::Visitor<'de> for FirstLast {
        type Value = Option<[f64; 2]>;

        fn visit_unit<E: serde::de::Error>(self) -> Result<Self::Value, E> {
            Ok(None)
        }

        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("[first, last]")
        }

        fn visit_seq<A: serde::de::SeqAccess<'de>>(
            self,
            mut seq: A,
        ) -> Result<Self::Value, A::Error> {
            let mut ends = Vec::new();
            while let Some(end) = seq.next_element::<f64>()? {
                ends.push(end);
            }
            match ends[..] {
                [first, last] => Ok(Some([first, last])),
                _ => Err(A::Error::invalid_length(ends.len(), &self)),
            }
        }
    }

    deserializer.deserialize_any(FirstLast)
}
