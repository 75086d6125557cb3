//! Issue 43: a reversal value that varies from target to target on a small plan (5
//! targets × 5 runs, the Bi of a worn section the issue quotes with their standard
//! errors: `tests/data/made/reversal_worn_5x5.py`) is confirmed in its per-target shape,
//! against tests simulated without it, and the compensation says what one backlash value
//! leaves of it.

use crate::common::axcheck;
use serde_json::Value;

const WORN: &str = "tests/data/made/reversal_worn_5x5.csv";
const BI_UM: [f64; 5] = [1.24, 4.37, -7.28, -2.31, -13.43];

fn diagnosis(file: &str) -> Value {
    let (code, out, err) = axcheck(&["diagnose", "--json", file]);
    assert_eq!(code, 0, "{err}");
    serde_json::from_str(&out).unwrap()
}

#[test]
fn a_reversal_that_varies_per_target_is_confirmed_on_five_targets() {
    let d = diagnosis(WORN);
    let found: Vec<&Value> = (d["findings"].as_array().unwrap().iter())
        .filter(|f| f["effect"] == "reversal_variation")
        .collect();
    assert_eq!(found.len(), 1, "{:#}", d["findings"]);
    let f = found[0];
    assert_eq!(f["labels"]["fitted_shape"], "per_target", "{f:#}");
    for (i, want) in BI_UM.iter().enumerate() {
        let got = f["params"][format!("reversal_target_{}_um", i + 1)]
            .as_f64()
            .unwrap();
        // The readings are rounded to 0.001 µm.
        assert!(
            (got - want).abs() < 0.002,
            "target {}: {got} vs {want}",
            i + 1
        );
    }
    let range = f["params"]["reversal_range_um"].as_f64().unwrap();
    assert!((range - 17.80).abs() < 0.002, "{range}");
    assert!(
        f["message"]
            .as_str()
            .unwrap()
            .starts_with("the reversal value changes from target to target, range 17.80 µm: Bi = 1.24 µm at 15 mm, 4.37 µm at 25 mm, -7.28 µm at 35 mm"),
        "{f:#}"
    );
    assert!(
        f["advice"]
            .as_str()
            .unwrap()
            .contains("leaves up to ±8.90 µm"),
        "{f:#}"
    );
    assert!(
        d["unconfirmed"].as_array().unwrap().is_empty(),
        "{:#}",
        d["unconfirmed"]
    );
    // How it was judged: its shape chosen among those 5 targets offer, its gain against
    // tests simulated without it.
    let gain = (d["term_gains"].as_array().unwrap().iter())
        .find(|g| g["effect"] == "reversal_variation")
        .unwrap();
    assert_eq!(gain["null"], "simulated_tests");
    assert_eq!(gain["shape"], "per_target");
    assert_eq!(gain["kept"], true);
    let shapes: Vec<&str> = (gain["shapes"].as_array().unwrap().iter())
        .map(|s| s["shape"].as_str().unwrap())
        .collect();
    assert_eq!(shapes, ["line", "per_target"]);
    assert!(gain["gain_pct"].as_f64().unwrap() > gain["threshold_pct"].as_f64().unwrap());
    // What the plan could confirm: a reversal changing along the axis, and 10 targets.
    let x = (d["detectable"].as_array().unwrap().iter())
        .find(|x| x["effect"] == "reversal_variation")
        .unwrap();
    assert_eq!(d["detectable"].as_array().unwrap().len(), 8, "every effect");
    assert_eq!(x["measure"], "change_over_axis_um");
    assert_eq!(x["more_targets"], 10);
    let (size, more) = (
        x["size"].as_f64().unwrap(),
        x["size_with_more_targets"].as_f64().unwrap(),
    );
    assert!(size > 0.0 && more < size, "{x:#}");
    assert!(
        x["advice"]
            .as_str()
            .unwrap()
            .starts_with("with 5 targets and 5 runs a reversal variation under "),
        "{x:#}"
    );
    // The extended model carries the reversal per target.
    let model = d["extended_model"].as_str().unwrap();
    assert!(model.contains("reversal_knots"), "{model}");
}

/// A table with one correction per position for both directions (Siemens' encoder
/// compensation beside its backlash) leaves the reversal to one backlash value: the
/// warning gives half the range; LinuxCNC's and FANUC's bidirectional tables correct each
/// direction per position and get no such warning.
#[test]
fn one_backlash_value_is_warned_to_leave_half_the_range() {
    let (code, out, err) = axcheck(&["compensate", WORN, "--controller", "siemens-840d"]);
    assert_eq!(code, 0, "{err}");
    let all = format!("{out}\n{err}");
    assert!(
        all.contains("the reversal value changes along the axis (Bi range 17.80 µm): one backlash value for the axis removes the mean reversal and leaves up to ±8.90 µm, half that range"),
        "{all}"
    );
    for controller in ["linuxcnc", "fanuc"] {
        let (code, out, err) = axcheck(&["compensate", WORN, "--controller", controller]);
        assert_eq!(code, 0, "{err}");
        assert!(
            !format!("{out}{err}").contains("one backlash value"),
            "{controller}: {out}{err}"
        );
    }
}
