//! Campaign files: machines, their axes and the measurement files, loaded and validated.
//!
//! A campaign that cannot be read at all (bad YAML, a broken `campaign:` block) is an
//! error. A broken machine or axis is kept as an entry with its error, so the rest of the
//! campaign is still evaluated. Every error names the campaign file, line and column.

pub mod data;
pub mod model;

pub use model::{
    Air, AxisRaw, CampaignInfo, Conditions, Instrument, MachineInfo, Nde, OutputOptions,
    SensorKind, TemperatureSensor,
};

use crate::evaluate::StandardId;
use crate::units::Travel;
use crate::yaml::{self, LocationIndex, deserialize_at};
use data::DataSource;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A campaign that could not be read at all.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct CampaignError(pub String);

/// A loaded campaign.
#[derive(Debug, Clone)]
pub struct Campaign {
    /// The campaign file as given.
    pub file: PathBuf,
    /// Folder that relative paths resolve against.
    pub dir: PathBuf,
    pub info: CampaignInfo,
    /// Standard for axes that name none.
    pub standard: StandardId,
    pub machines: Vec<Machine>,
}

#[derive(Debug, Clone)]
pub struct Machine {
    pub info: MachineInfo,
    pub axes: Vec<AxisEntry>,
}

/// An axis as loaded: ready to evaluate, or the reason it cannot be.
#[derive(Debug, Clone)]
pub struct AxisEntry {
    /// Axis name (or `axis N` when even the name could not be read).
    pub name: String,
    pub spec: Result<AxisSpec, String>,
}

/// A validated axis.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisSpec {
    pub raw: AxisRaw,
    pub standard: StandardId,
    /// Spec name or path (the axis's or the campaign's).
    pub spec: Option<String>,
    pub data: DataSource,
    /// Line of the axis in the campaign file.
    pub line: usize,
}

impl Campaign {
    /// Loads a campaign file from disk.
    pub fn load(path: &Path) -> Result<Campaign, CampaignError> {
        let text = std::fs::read_to_string(path).map_err(|e| {
            CampaignError(format!(
                "{}: cannot read the campaign file: {e}",
                path.display()
            ))
        })?;
        Campaign::parse(&text, path)
    }

    /// Parses campaign `text` read from `path`.
    pub fn parse(text: &str, path: &Path) -> Result<Campaign, CampaignError> {
        let file = path.display().to_string();
        // Two independent passes over the text: the values and their locations.
        let (value, index) = rayon::join(
            || serde_norway::from_str::<serde_norway::Value>(text),
            || LocationIndex::new(text),
        );
        let value = value.map_err(|e| CampaignError(yaml::syntax_error(&e, &file, text)))?;
        let fail = |located: yaml::Located| CampaignError(located.in_file(&file));
        let serde_norway::Value::Mapping(mut top) = value else {
            return Err(CampaignError(format!(
                "{file}: expected a mapping with `campaign:` and `machines:`"
            )));
        };
        for key in top.keys() {
            let name = key.as_str().unwrap_or("");
            if name != "campaign" && name != "machines" {
                let hint = crate::suggest::hint(name, &["campaign", "machines"]);
                return Err(fail(yaml::Located {
                    at: index.key(name),
                    message: format!("unknown key `{name}`{hint}; expected campaign, machines"),
                }));
            }
        }
        let info_value = top.remove("campaign").ok_or_else(|| {
            CampaignError(format!(
                "{file}: missing the `campaign:` block (name, date, standard …)"
            ))
        })?;
        let info: CampaignInfo = deserialize_at(info_value, "campaign", &index).map_err(fail)?;
        let standard = match &info.standard {
            None => StandardId::Iso230_2,
            Some(s) => StandardId::parse(s).ok_or_else(|| {
                fail(yaml::Located {
                    at: index.value("campaign.standard"),
                    message: unknown_standard(s),
                })
            })?,
        };
        if let Some(date) = &info.date
            && !is_iso_date(date)
        {
            return Err(fail(yaml::Located {
                at: index.value("campaign.date"),
                message: format!("campaign.date: expected YYYY-MM-DD, found `{date}`"),
            }));
        }
        let machines_value = top
            .remove("machines")
            .ok_or_else(|| CampaignError(format!("{file}: missing the `machines:` list")))?;
        let serde_norway::Value::Sequence(machine_values) = machines_value else {
            return Err(fail(yaml::Located {
                at: index.value("machines"),
                message: "machines: expected a list of machines".into(),
            }));
        };
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        // Machines are independent: load them in parallel (a fleet has thousands of axes).
        use rayon::prelude::*;
        let machines: Vec<Machine> = machine_values
            .into_par_iter()
            .enumerate()
            .map(|(m, value)| {
                load_machine(
                    value,
                    &format!("machines[{m}]"),
                    &index,
                    &file,
                    &info,
                    standard,
                )
            })
            .collect();
        let campaign = Campaign {
            file: path.to_path_buf(),
            dir,
            info,
            standard,
            machines,
        };
        campaign.check_unique_names(&index)?;
        Ok(campaign)
    }

    /// Every axis entry with its machine.
    pub fn axes(&self) -> impl Iterator<Item = (&Machine, &AxisEntry)> {
        self.machines
            .iter()
            .flat_map(|m| m.axes.iter().map(move |a| (m, a)))
    }

    fn check_unique_names(&self, index: &LocationIndex) -> Result<(), CampaignError> {
        let file = self.file.display().to_string();
        let mut machines = BTreeMap::new();
        for (m, machine) in self.machines.iter().enumerate() {
            if let Some(first) = machines.insert(machine.info.id.clone(), m) {
                let at = index.value(&format!("machines[{m}].id"));
                return Err(CampaignError(
                    yaml::Located {
                        at,
                        message: format!(
                            "machine id `{}` is used twice (machines[{first}] and machines[{m}]); ids must be unique",
                            machine.info.id
                        ),
                    }
                    .in_file(&file),
                ));
            }
        }
        Ok(())
    }
}

fn unknown_standard(s: &str) -> String {
    format!("unknown standard `{s}`; expected iso230-2, gbt17421.2, gost27843, vdi3441 or nmtba")
}

fn is_iso_date(s: &str) -> bool {
    let b = s.as_bytes();
    b.len() == 10
        && b[4] == b'-'
        && b[7] == b'-'
        && b.iter()
            .enumerate()
            .all(|(k, c)| k == 4 || k == 7 || c.is_ascii_digit())
        && matches!(s[5..7].parse::<u32>(), Ok(1..=12))
        && matches!(s[8..10].parse::<u32>(), Ok(1..=31))
}

fn load_machine(
    value: serde_norway::Value,
    base: &str,
    index: &LocationIndex,
    file: &str,
    campaign: &CampaignInfo,
    standard: StandardId,
) -> Machine {
    let fallback_id = value
        .get("id")
        .and_then(|v| v.as_str())
        .map_or_else(|| base.to_string(), str::to_string);
    // Only a broken machine needs its axes' names; take them, not a copy of the axes.
    let axis_names: Vec<String> = match value.get("axes") {
        Some(serde_norway::Value::Sequence(items)) => items
            .iter()
            .enumerate()
            .map(|(a, v)| axis_name(v, a))
            .collect(),
        _ => Vec::new(),
    };
    match deserialize_at::<MachineInfo>(value, base, index) {
        Ok(mut info) => {
            let axes = match std::mem::take(&mut info.axes) {
                serde_norway::Value::Sequence(items) => items
                    .into_iter()
                    .enumerate()
                    .map(|(a, v)| {
                        load_axis(
                            v,
                            &format!("{base}.axes[{a}]"),
                            index,
                            file,
                            campaign,
                            standard,
                        )
                    })
                    .collect(),
                serde_norway::Value::Null => Vec::new(),
                _ => vec![AxisEntry {
                    name: "axes".into(),
                    spec: Err(yaml::Located {
                        at: index.value(&format!("{base}.axes")),
                        message: format!("{base}.axes: expected a list of axes"),
                    }
                    .in_file(file)),
                }],
            };
            Machine { info, axes }
        }
        Err(e) => {
            // The machine is broken: each of its axes reports why (or one entry if none).
            let message = e.in_file(file);
            let names = if axis_names.is_empty() {
                vec!["(all axes)".to_string()]
            } else {
                axis_names
            };
            Machine {
                info: MachineInfo {
                    id: fallback_id,
                    ..MachineInfo::default()
                },
                axes: names
                    .into_iter()
                    .map(|name| AxisEntry {
                        name,
                        spec: Err(message.clone()),
                    })
                    .collect(),
            }
        }
    }
}

fn axis_name(value: &serde_norway::Value, a: usize) -> String {
    value
        .get("name")
        .and_then(|v| {
            v.as_str()
                .map(str::to_string)
                .or_else(|| v.as_i64().map(|n| n.to_string()))
        })
        .unwrap_or_else(|| format!("axis {}", a + 1))
}

fn load_axis(
    value: serde_norway::Value,
    base: &str,
    index: &LocationIndex,
    file: &str,
    campaign: &CampaignInfo,
    default_standard: StandardId,
) -> AxisEntry {
    let name = axis_name(
        &value,
        base.rsplit('[')
            .next()
            .and_then(|s| s.trim_end_matches(']').parse().ok())
            .unwrap_or(0),
    );
    let line = index.value(base).map_or(0, |(l, _)| l);
    let spec = (|| -> Result<AxisSpec, yaml::Located> {
        let raw: AxisRaw = deserialize_at(value, base, index)?;
        let at = |key: &str| index.value(&format!("{base}.{key}"));
        let standard = match &raw.standard {
            None => default_standard,
            Some(s) => StandardId::parse(s).ok_or_else(|| yaml::Located {
                at: at("standard"),
                message: format!("{base}.standard: {}", unknown_standard(s)),
            })?,
        };
        let data = DataSource::from_value(&raw.data).map_err(|message| yaml::Located {
            at: at("data"),
            message: format!("{base}.data: {message}"),
        })?;
        if let Some(t) = raw.travel {
            let ok = match t {
                Travel::Length(l) => l > 0.0 && l.is_finite(),
                Travel::Range([a, b]) => b > a && a.is_finite() && b.is_finite(),
            };
            if !ok {
                return Err(yaml::Located {
                    at: at("travel"),
                    message: format!(
                        "{base}.travel: expected a length > 0 or [start, end] with end > start"
                    ),
                });
            }
        }
        if let Some([a, b]) = raw.measurement_travel
            && !(b > a && a.is_finite() && b.is_finite())
        {
            return Err(yaml::Located {
                at: at("measurement_travel"),
                message: format!(
                    "{base}.measurement_travel: expected [first, last] with last > first"
                ),
            });
        }
        if let Some(p) = raw.pitch
            && !(p > 0.0 && p.is_finite())
        {
            return Err(yaml::Located {
                at: at("pitch"),
                message: format!("{base}.pitch: expected a pitch > 0"),
            });
        }
        for (key, limit) in &raw.tolerances {
            if !crate::evaluate::catalogue::is_limitable_key(key) {
                let known = crate::evaluate::catalogue::limitable_keys();
                let hint = crate::suggest::hint(key, known);
                return Err(yaml::Located {
                    at: index.key(&format!("{base}.tolerances.{key}")),
                    message: format!("{base}.tolerances: unknown parameter `{key}`{hint}"),
                });
            }
            if !(*limit >= 0.0 && limit.is_finite()) {
                return Err(yaml::Located {
                    at: index.value(&format!("{base}.tolerances.{key}")),
                    message: format!("{base}.tolerances.{key}: expected a limit ≥ 0"),
                });
            }
        }
        Ok(AxisSpec {
            standard,
            // `spec: none` opts an axis out of the campaign's default spec.
            spec: match raw.spec.as_deref() {
                Some("none") => None,
                Some(name) => Some(name.to_string()),
                None => campaign.spec.clone().filter(|s| s != "none"),
            },
            data,
            line,
            raw,
        })
    })()
    .map_err(|e| e.in_file(file));
    AxisEntry { name, spec }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        assert_eq!(x.raw.tolerances["A"], 12.0);
        assert_eq!(x.spec.as_deref(), Some("general"));
        assert_eq!(x.line, 7);
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
        let e = axes[0].spec.as_ref().unwrap_err();
        assert!(e.starts_with("plant/campaign.yaml:12:9: machines[0].axes[0].tolerance: unknown key `tolerance` (did you mean `tolerances`?)"), "{e}");
        assert!(axes[1].spec.is_ok() && axes[2].spec.is_ok());
        let text = GOOD.replace("kind: rotary", "kind: rotory");
        let c = parse(&text).unwrap();
        let e = c.machines[0].axes[2].spec.as_ref().unwrap_err();
        assert!(
            e.starts_with(
                "plant/campaign.yaml:18:15: machines[0].axes[2].kind: unknown variant `rotory`"
            ),
            "{e}"
        );
    }

    #[test]
    fn campaign_level_errors() {
        let e = parse("campaign: {name: x, dat: 2026-01-01}\nmachines: []\n").unwrap_err();
        assert!(
            e.0.starts_with(
                "plant/campaign.yaml:1:21: campaign.dat: unknown key `dat` (did you mean `date`?)"
            ),
            "{e}"
        );
        let e = parse("campaign: {name: x, date: 2026-13-01}\nmachines: []\n").unwrap_err();
        assert!(e.0.contains("1:27") && e.0.contains("YYYY-MM-DD"), "{e}");
        let e = parse("campaign: {name: x}\nmachine: []\n").unwrap_err();
        assert!(
            e.0.contains("2:1: unknown key `machine` (did you mean `machines`?)"),
            "{e}"
        );
        let e = parse("campaign:\n\tname: x\nmachines: []\n").unwrap_err();
        assert!(
            e.0.starts_with("plant/campaign.yaml:2:1:") && e.0.contains("indented with a tab"),
            "{e}"
        );
        let e = parse("campaign: {name: x\n").unwrap_err();
        assert!(e.0.starts_with("plant/campaign.yaml:"), "{e}");
    }

    #[test]
    fn a_broken_machine_fails_its_axes() {
        let text = GOOD.replace("    model: DMU 50", "    modle: DMU 50");
        let c = parse(&text).unwrap();
        assert_eq!(c.machines[0].axes.len(), 3);
        for a in &c.machines[0].axes {
            let e = a.spec.as_ref().unwrap_err();
            assert!(
                e.contains("4:5") && e.contains("did you mean `model`"),
                "{e}"
            );
        }
        assert_eq!(c.machines[0].axes[0].name, "X");
    }
}
