//! Campaign files: machines, their axes and the measurement files, loaded and validated.
//!
//! A campaign that cannot be read at all (bad YAML, a broken `campaign:` block) is an
//! error. A broken machine or axis is kept as an entry with its error, so the rest of the
//! campaign is still evaluated. Every error names the campaign file, line and column.

pub mod certificate;
pub mod clause7_1;
mod cross;
pub mod data;
pub(crate) mod dates;
mod file_info;
pub mod geometry;
mod load;
pub mod model;
pub mod report_options;
pub mod squareness;
pub mod stages;

pub use model::{
    Air, AxisRaw, CampaignInfo, Conditions, InstrumentEntry, MachineInfo, Nde, OutputOptions,
    SensorKind, TemperatureSensor, ToolPointRaw, Unjudged,
};
pub use report_options::{ReportOptions, report_lang};

use crate::evaluate::StandardId;
use crate::yaml::{self, Located, LocationIndex, YamlError, deserialize_at};
use data::DataSource;
use serde_norway::Value;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// A campaign that could not be read at all.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CampaignError {
    /// The file cannot be read from disk.
    #[error("{file}: cannot read the campaign file: {reason}")]
    Unreadable { file: String, reason: String },
    /// The file is not a campaign: bad YAML, a broken top level or `campaign:` block,
    /// or two machines with one id.
    #[error(transparent)]
    Invalid(#[from] YamlError),
}

/// A loaded campaign.
#[derive(Debug, Clone)]
pub struct Campaign {
    /// The campaign file as given.
    pub file: PathBuf,
    /// Folder that relative paths resolve against.
    pub dir: PathBuf,
    pub info: CampaignInfo,
    /// `campaign.history` resolved against the campaign's folder (checked by the path rule).
    pub history: Option<PathBuf>,
    /// Standard for axes that name none.
    pub standard: StandardId,
    pub machines: Vec<Machine>,
    /// The SHA-256 of the campaign file's bytes, when it was loaded from one.
    pub sha256: Option<String>,
}

#[derive(Debug, Clone)]
pub struct Machine {
    pub info: MachineInfo,
    pub axes: Vec<AxisEntry>,
    /// Its `squareness:` pairs, each ready or with its error.
    pub squareness: Vec<squareness::SquarenessEntry>,
}

/// An axis as loaded: ready to evaluate, or the reason it cannot be.
#[derive(Debug, Clone)]
pub struct AxisEntry {
    /// Axis name (or `axis N` when even the name could not be read).
    pub name: String,
    /// Shared: each test of the axis holds it (a fleet's gate copied it for each).
    pub spec: Result<Arc<AxisSpec>, crate::yaml::YamlError>,
}

/// A validated axis.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisSpec {
    pub raw: AxisRaw,
    pub standard: StandardId,
    /// Spec name or path (the axis's or the campaign's).
    pub spec: Option<String>,
    pub data: DataSource,
    /// Where the axis is written in the campaign file.
    pub at: Place,
}

/// Where an entry is written in a file: its path in the document, its line found in the
/// file's location index only when asked (an error message), so that a campaign loaded
/// without an error is parsed once.
#[derive(Debug, Clone)]
pub struct Place {
    index: Arc<LocationIndex>,
    path: String,
}

impl Place {
    pub fn new(index: &Arc<LocationIndex>, path: &str) -> Place {
        Place {
            index: index.clone(),
            path: path.to_string(),
        }
    }

    /// The entry's line (1-based; 0 when it cannot be found).
    pub fn line(&self) -> usize {
        self.index.value(&self.path).map_or(0, |(l, _)| l)
    }

    /// Where the entry's `key` is written, as `path.key` with its line: the axis's own,
    /// else the campaign's (`campaign.spec` for an axis that inherits it), else the entry.
    pub fn key(&self, key: &str) -> (String, usize) {
        let own = format!("{}.{key}", self.path);
        let campaign = format!("campaign.{key}");
        for path in [own, campaign] {
            if let Some((line, _)) = self.index.key(&path) {
                return (path, line);
            }
        }
        (self.path.clone(), self.line())
    }
}

/// Two places are the same path in the document.
impl PartialEq for Place {
    fn eq(&self, other: &Place) -> bool {
        self.path == other.path
    }
}

/// The two keys of a campaign file.
const TOP_KEYS: [&str; 2] = ["campaign", "machines"];

impl Campaign {
    /// Loads a campaign file from disk (a regular file only: [`crate::files`]).
    pub fn load(path: &Path) -> Result<Campaign, CampaignError> {
        let (text, sha256) =
            crate::files::read_to_string_hashed(path).map_err(|e| CampaignError::Unreadable {
                file: path.display().to_string(),
                reason: e.to_string(),
            })?;
        Ok(Campaign {
            sha256: Some(sha256),
            ..Campaign::parse(&text, path)?
        })
    }

    /// Parses campaign `text` read from `path`.
    pub fn parse(text: &str, path: &Path) -> Result<Campaign, CampaignError> {
        let file = path.display().to_string();
        let (value, index) = yaml::parse_long_list(text, &file, "machines")?;
        let index = Arc::new(index);
        let fail = |located: Located| CampaignError::Invalid(located.in_file(&file));
        let top = top_level(&value, &index).map_err(fail)?;
        // Where the document starts, for what it lacks (looked up only then).
        let root = || index.value("");
        let info_value = top.get("campaign").ok_or_else(|| {
            fail(Located::new(
                root(),
                "missing the `campaign:` block (name, date, standard …)",
            ))
        })?;
        let info: CampaignInfo = deserialize_at(info_value, "campaign", &index).map_err(fail)?;
        let standard = match &info.standard {
            None => StandardId::Iso230_2,
            Some(s) => parse_standard(s, "campaign.standard", &index).map_err(fail)?,
        };
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let history = history_dir(&info, &dir, &index).map_err(fail)?;
        check_horizon(&info, &index).map_err(fail)?;
        if let Some(c) = &info.certificate {
            certificate::check(c, "campaign.certificate", info.date.as_deref(), &index)
                .map_err(fail)?;
        }
        let machine_values = match top.get("machines") {
            None => return Err(fail(Located::new(root(), "missing the `machines:` list"))),
            Some(Value::Sequence(items)) => items,
            Some(other) => {
                let message = format!(
                    "machines: expected a list of machines, got {}",
                    yaml::describe(other)
                );
                return Err(fail(Located::new(index.value("machines"), message)));
            }
        };
        // Machines are independent: load them in parallel (a fleet has thousands of axes).
        use rayon::prelude::*;
        let machines: Vec<Machine> = machine_values
            .par_iter()
            .enumerate()
            .map(|(m, value)| {
                let base = format!("machines[{m}]");
                load::machine(value, &base, &index, &file, &info, standard)
            })
            .collect();
        let campaign = Campaign {
            file: path.to_path_buf(),
            dir,
            info,
            history,
            standard,
            machines,
            sha256: None,
        };
        campaign.check_unique_names(&index).map_err(fail)?;
        Ok(campaign)
    }

    /// Every axis entry with its machine.
    pub fn axes(&self) -> impl Iterator<Item = (&Machine, &AxisEntry)> {
        self.machines
            .iter()
            .flat_map(|m| m.axes.iter().map(move |a| (m, a)))
    }

    fn check_unique_names(&self, index: &LocationIndex) -> Result<(), Located> {
        let mut machines = BTreeMap::new();
        for (m, machine) in self.machines.iter().enumerate() {
            if let Some(first) = machines.insert(machine.info.id.clone(), m) {
                return Err(Located::new(
                    index.value(&format!("machines[{m}].id")),
                    format!(
                        "machine id `{}` is used twice (machines[{first}] and machines[{m}]); ids must be unique",
                        machine.info.id
                    ),
                ));
            }
            unique_axis_names(machine, m, index)?;
        }
        Ok(())
    }
}

/// The axes of one machine have different names: machine and axis are one history
/// series, and two axes of one name would write one series.
fn unique_axis_names(machine: &Machine, m: usize, index: &LocationIndex) -> Result<(), Located> {
    let mut axes = BTreeMap::new();
    for (a, entry) in machine.axes.iter().enumerate() {
        let Ok(spec) = &entry.spec else { continue };
        // One axis may hold several tests: positioning, EYX, EZX, EBX …
        let test = (
            spec.raw.name.as_str(),
            spec.raw.test.key(),
            geometry::symbol(&spec.raw),
        );
        if let Some(first) = axes.insert(test, a) {
            return Err(Located::new(
                index.value(&format!("machines[{m}].axes[{a}].name")),
                format!(
                    "machines[{m}].axes[{a}].name: axis `{}` of machine `{}` is named twice (axes[{first}] and axes[{a}]); each axis of a machine needs its own name (or, for one axis's other laser tests, its own `test:` and `direction:` or `about:`)",
                    spec.raw.name, machine.info.id
                ),
            ));
        }
    }
    Ok(())
}

/// The top level: a mapping of `campaign:` and `machines:` and nothing else.
fn top_level<'v>(
    value: &'v Value,
    index: &LocationIndex,
) -> Result<&'v serde_norway::Mapping, Located> {
    let top = match value {
        Value::Mapping(top) => top,
        Value::Null => {
            return Err(Located::new(
                None,
                "expected a mapping with `campaign:` and `machines:`, got an empty file",
            ));
        }
        other => {
            return Err(Located::new(
                index.value(""),
                format!(
                    "expected a mapping with `campaign:` and `machines:`, got {}",
                    yaml::describe(other)
                ),
            ));
        }
    };
    for key in top.keys() {
        let name = key.as_str().map_or_else(
            || {
                serde_norway::to_string(key)
                    .unwrap_or_default()
                    .trim()
                    .to_string()
            },
            str::to_string,
        );
        let name = name.as_str();
        if !TOP_KEYS.contains(&name) {
            let hint = crate::suggest::hint(name, &TOP_KEYS);
            return Err(Located::new(
                index.key(name),
                format!("unknown key `{name}`{hint}; expected campaign, machines"),
            ));
        }
    }
    Ok(top)
}

/// `campaign.trend_horizon_years`, when given, is a number of years > 0.
fn check_horizon(info: &CampaignInfo, index: &LocationIndex) -> Result<(), Located> {
    let Some(years) = info.trend_horizon_years else {
        return Ok(());
    };
    crate::trend::fit::TrendOptions::with_horizon(years)
        .map(|_| ())
        .map_err(|e| {
            let at = index.value("campaign.trend_horizon_years");
            Located::new(at, format!("campaign.trend_horizon_years: {e}"))
        })
}

/// `campaign.history` inside the campaign's folder (unless `allow_outside_paths`).
fn history_dir(
    info: &CampaignInfo,
    dir: &Path,
    index: &LocationIndex,
) -> Result<Option<PathBuf>, Located> {
    let Some(history) = &info.history else {
        return Ok(None);
    };
    let located = |message: String| {
        Located::new(
            index.value("campaign.history"),
            format!("campaign.history: {message}"),
        )
    };
    if history.trim().is_empty() {
        return Err(located(
            "expected a folder, e.g. `history: history`, got an empty text".into(),
        ));
    }
    crate::files::Root::campaign(dir, info.allow_outside_paths)
        .resolve(history)
        .map(Some)
        .map_err(|refused| located(refused.to_string()))
}

/// The standard named at `path`.
fn parse_standard(name: &str, path: &str, index: &LocationIndex) -> Result<StandardId, Located> {
    const NAMES: [&str; 5] = ["iso230-2", "gbt17421.2", "gost27843", "vdi3441", "nmtba"];
    StandardId::parse(name).ok_or_else(|| {
        let hint = crate::suggest::hint(name, &NAMES);
        let names: Vec<String> = NAMES.map(str::to_string).to_vec();
        Located::new(
            index.value(path),
            format!(
                "{path}: unknown standard `{name}`{hint}; expected {}",
                yaml::or_list(&names)
            ),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::evaluate::ParamKey;
    use crate::units::Travel;

    fn parse(text: &str) -> Result<Campaign, CampaignError> {
        Campaign::parse(text, Path::new("plant/campaign.yaml"))
    }

    const GOOD: &str =
        "campaign: {name: Plant 2, date: 2026-11-20, standard: iso230-2, spec: general}
machines:
  - id: VMC-07
    model: DMU 50
    type: vertical machining centre
    axes:
      - name: X
        kind: linear
        travel: 1200
        measurement_travel: [5, 1195]
        data: data/x.csv
        tolerances: {A: 12, R: 6}
      - name: Y
        kind: linear
        data: [data/y1.csv, data/y2.csv]
        spec: precision
      - name: C
        kind: rotary
        standard: gost27843
        data: {dir: data/c, glob: \"c-*.csv\"}
";

    #[test]
    fn loads_the_core_keys() {
        let c = parse(GOOD).unwrap();
        assert_eq!(c.info.name, "Plant 2");
        assert_eq!(c.dir, Path::new("plant"));
        let axes: Vec<&AxisEntry> = c.axes().map(|(_, a)| a).collect();
        assert_eq!(axes.len(), 3);
        let x = axes[0].spec.as_ref().unwrap();
        assert_eq!(x.raw.travel, Some(Travel::Length(1200.0)));
        assert_eq!(x.raw.tolerances[&ParamKey::A], 12.0);
        assert_eq!(x.spec.as_deref(), Some("general"));
        assert_eq!(x.at.line(), 7);
        let y = axes[1].spec.as_ref().unwrap();
        assert_eq!(y.spec.as_deref(), Some("precision"));
        assert!(matches!(y.data, DataSource::Files(ref f) if f.len() == 2));
        let c_axis = axes[2].spec.as_ref().unwrap();
        assert_eq!(c_axis.standard, StandardId::Gost27843);
    }

    #[test]
    fn a_broken_axis_fails_alone_with_its_location() {
        let text = GOOD.replace(
            "        tolerances: {A: 12, R: 6}",
            "        tolerance: {A: 12}",
        );
        let c = parse(&text).unwrap();
        let axes: Vec<&AxisEntry> = c.axes().map(|(_, a)| a).collect();
        let e = axes[0].spec.as_ref().unwrap_err().to_string();
        // `tolerance` is a key of the other laser tests since issue 46: a mapping there
        // points to `tolerances`.
        assert!(e.starts_with("plant/campaign.yaml:12:20: machines[0].axes[0].tolerance: limits by parameter are `tolerances: {A: …}` (did you mean `tolerances`?)"), "{e}");
        assert!(axes[1].spec.is_ok() && axes[2].spec.is_ok());
        let text = GOOD.replace("kind: rotary", "kind: rotory");
        let c = parse(&text).unwrap();
        let e = c.machines[0].axes[2].spec.as_ref().unwrap_err().to_string();
        assert_eq!(
            e,
            "plant/campaign.yaml:18:15: machines[0].axes[2].kind: unknown kind `rotory` (did you mean `rotary`?); expected linear or rotary"
        );
    }

    #[test]
    fn campaign_level_errors() {
        let e = |text: &str| parse(text).unwrap_err().to_string();
        assert!(
            e("campaign: {name: x, dat: 2026-01-01}\nmachines: []\n").starts_with(
                "plant/campaign.yaml:1:21: campaign.dat: unknown key `dat` (did you mean `date`?)"
            )
        );
        assert_eq!(
            e("campaign: {name: x, date: 2026-13-01}\nmachines: []\n"),
            "plant/campaign.yaml:1:27: campaign.date: expected a date YYYY-MM-DD, got the text `2026-13-01`"
        );
        assert_eq!(
            e("campaign: {name: x}\nmachine: []\n"),
            "plant/campaign.yaml:2:1: unknown key `machine` (did you mean `machines`?); expected campaign, machines"
        );
        let tab = e("campaign:\n\tname: x\nmachines: []\n");
        assert!(
            tab.starts_with("plant/campaign.yaml:2:1:") && tab.contains("indented with a tab"),
            "{tab}"
        );
        assert_eq!(
            e("campaign: {name: x\n"),
            "plant/campaign.yaml:2:1: did not find expected ',' or '}' (while parsing a flow mapping that starts at 1:11)"
        );
        assert_eq!(
            e("machines: []\n"),
            "plant/campaign.yaml:1:1: missing the `campaign:` block (name, date, standard …)"
        );
        assert_eq!(
            e("campaign: {name: x}\nmachines: {a: 1}\n"),
            "plant/campaign.yaml:2:11: machines: expected a list of machines, got a mapping with 1 key"
        );
        assert_eq!(
            e(""),
            "plant/campaign.yaml:1:1: expected a mapping with `campaign:` and `machines:`, got an empty file"
        );
        assert_eq!(
            e("campaign: {name: x}\nmachines: []\n---\nmachines: []\n"),
            "plant/campaign.yaml:3:1: more than one YAML document (a `---` line starts another); the file holds one"
        );
        assert!(matches!(
            parse("campaign: {name: x, standard: gots27843}\nmachines: []\n"),
            Err(CampaignError::Invalid(YamlError {
                line: 1,
                column: 31,
                ..
            }))
        ));
    }

    #[test]
    fn a_broken_machine_fails_its_axes() {
        let text = GOOD.replace("    model: DMU 50", "    modle: DMU 50");
        let c = parse(&text).unwrap();
        assert_eq!(c.machines[0].axes.len(), 3);
        for a in &c.machines[0].axes {
            let e = a.spec.as_ref().unwrap_err().to_string();
            assert!(
                e.contains("4:5") && e.contains("did you mean `model`"),
                "{e}"
            );
        }
        assert_eq!(c.machines[0].axes[0].name, "X");
    }
}
