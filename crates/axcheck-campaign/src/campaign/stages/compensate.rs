//! The compensation stage's configuration as the campaign states it: the table active
//! during the test and the one it verifies, read from the controller's files beside the
//! data (the same path rules), and what a re-measurement is compared with. The reading
//! of a table file ([`read_table`]) and of an active state ([`active_state`]) is the one
//! the commands' `--active`, `--table` and `--other` use too.

use crate::campaign::AxisSpec;
use crate::campaign::model::{ActiveRaw, ActiveStated, CompensationRaw};
use crate::compensate::controllers::{Controller, ReadAs};
use crate::compensate::{self, Active, Settings, Table, TableSlot};
use crate::files::Root as Files;
use crate::measurement::AxisData;
use crate::units::AxisKind;
use std::path::{Path, PathBuf};

/// Why a table the campaign states for a test (active during it, or verified by it), or
/// the measurement before a verified table, cannot be used: the test's compensation is
/// refused and its verification not made, with this reason. The commands' table files
/// fail with the same reasons, `key` naming their option.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StatedTableError {
    /// The campaign's folder rules refuse the path (`compensation.active: …`).
    #[error("{key}: {refused}")]
    Path {
        key: &'static str,
        refused: crate::files::PathRefused,
    },
    #[error("{}: cannot read the table: {reason}", path.display())]
    Unreadable { path: PathBuf, reason: String },
    /// The file is no table of the controller's format.
    #[error("{}: {reason} (read as a {controller} table for {key})", path.display())]
    NotATable {
        path: PathBuf,
        reason: String,
        controller: &'static str,
        key: &'static str,
    },
    /// The measurement before the table was loaded cannot be read.
    #[error(transparent)]
    Before(Box<crate::measurement::ReadError>),
    #[error("the verified table is empty")]
    Empty,
    #[error("verification: {0}")]
    Verification(#[from] crate::verify::VerifyError),
}

/// Where a table file is: a path the campaign names under `key` (read under its folder's
/// rules), or a path given on the command line by the option `key` (read as given).
#[derive(Debug, Clone, Copy)]
pub enum TableFile<'a> {
    Stated {
        files: &'a Files,
        file: &'a str,
        key: &'static str,
    },
    Given {
        path: &'a Path,
        key: &'static str,
    },
}

/// The table file `at` as `controller` reads it for an axis of `kind` (`axis`: its name
/// on the control, to pick its table from a file of several).
pub fn read_table(
    at: TableFile,
    controller: &dyn Controller,
    kind: AxisKind,
    axis: Option<&str>,
) -> Result<Table, StatedTableError> {
    let (path, text, key) = match at {
        TableFile::Stated { files, file, key } => {
            let path = files
                .resolve(file)
                .map_err(|refused| StatedTableError::Path { key, refused })?;
            let text = files.read_to_string(&path);
            (path, text, key)
        }
        TableFile::Given { path, key } => {
            (path.to_path_buf(), crate::files::read_to_string(path), key)
        }
    };
    let text = text.map_err(|e| StatedTableError::Unreadable {
        path: path.clone(),
        reason: e.to_string(),
    })?;
    controller
        .read(&text, ReadAs { kind, axis })
        .map_err(|e| StatedTableError::NotATable {
            path,
            reason: e.to_string(),
            controller: controller.name(),
            key,
        })
}

/// The compensation active during a test: the table `file` (read by `read`) and the
/// backlash parameter, each when stated.
pub fn active_state<E>(
    file: Option<&str>,
    backlash: Option<f64>,
    read: impl FnOnce(&str) -> Result<Table, E>,
) -> Result<Active, E> {
    Ok(Active {
        table: file.map(read).transpose()?,
        file: file.map(str::to_string),
        backlash,
    })
}

/// What a re-measurement is compared with: the measurement before, and the corrections
/// active then and loaded since, as the controller adds them.
#[derive(Debug, Clone)]
pub struct VerifyCase {
    pub before: AxisData,
    /// The measurement before as read: its file (as the campaign names it), the layout it
    /// was read as and its NDE correction, for its own judgement (as found).
    pub before_file: String,
    pub before_recognised: crate::measurement::Recognised,
    pub before_nde: Option<crate::nde::NdeCorrection>,
    pub old: Option<Table>,
    pub new: Table,
    /// The controller's name, for the effects of its own parameters.
    pub controller: &'static str,
    /// Notes on what was assumed (an unstated backlash).
    pub notes: Vec<String>,
}

/// The compensation settings of `axis` for `controller`, its active table read; or why
/// they cannot be had (a table file that is missing or unreadable, naming file and line).
pub fn settings(
    axis: &AxisSpec,
    controller: &dyn Controller,
    files: &Files,
) -> Result<Settings, StatedTableError> {
    let raw = axis.raw.compensation.clone().unwrap_or_default();
    let place = TableSlot {
        axis: raw.axis.clone(),
        measuring_system: raw.measuring_system,
        number: None,
    };
    let kind = axis.raw.kind;
    let active = match (&raw.active, &raw.verifies) {
        (Some(a), _) => Some(active(
            a,
            kind,
            controller,
            files,
            &place,
            "compensation.active",
        )?),
        // A re-measurement: the table it verifies was active.
        (None, Some(v)) => {
            let stated = ActiveStated {
                file: Some(v.table.clone()),
                backlash_um: v.backlash_um,
                backlash_arcsec: v.backlash_arcsec,
            };
            Some(active(
                &ActiveRaw::Stated(stated),
                kind,
                controller,
                files,
                &place,
                "compensation.verifies.table",
            )?)
        }
        (None, None) => None,
    };
    Ok(Settings {
        interval: raw.interval,
        reference: raw.reference,
        pitch: axis.raw.pitch,
        place,
        active,
        conditions: axis.raw.conditions.compensation.clone(),
    })
}

/// The active state given outside a campaign (the commands' `--active` and
/// `--active-backlash`, the Python package's `active` and `active_backlash`): a table file
/// given by the option `key`, `none` for no table, and the backlash; `None` when neither
/// says anything (the state is unknown).
pub fn given_active_state(
    table: Option<&str>,
    backlash: Option<f64>,
    key: &'static str,
    controller: &dyn Controller,
    kind: AxisKind,
    axis: Option<&str>,
) -> Result<Option<Active>, StatedTableError> {
    let file = match table {
        None if backlash.is_none() => return Ok(None),
        None | Some("none") => None,
        Some(path) => Some(path),
    };
    let active = active_state(file, backlash, |path| {
        let at = TableFile::Given {
            path: Path::new(path),
            key,
        };
        read_table(at, controller, kind, axis)
    })?;
    Ok(Some(active))
}

/// A stated active state, its table read as `controller` reads it.
fn active(
    raw: &ActiveRaw,
    kind: AxisKind,
    controller: &dyn Controller,
    files: &Files,
    place: &TableSlot,
    key: &'static str,
) -> Result<Active, StatedTableError> {
    let ActiveRaw::Stated(s) = raw else {
        return Ok(Active::default());
    };
    let backlash = s.backlash_um.or(s.backlash_arcsec);
    active_state(s.file.as_deref(), backlash, |file| {
        let at = TableFile::Stated { files, file, key };
        read_table(at, controller, kind, place.axis.as_deref())
    })
}

/// What the re-measurement of `axis` is compared with, when it `verifies` a table: the
/// measurement before (corrected as this test is), the correction active then and the one
/// loaded since.
pub(crate) fn verify_case(
    axis: &AxisSpec,
    controller: &dyn Controller,
    files: &Files,
    settings: &Settings,
) -> Option<Result<VerifyCase, StatedTableError>> {
    let raw: &CompensationRaw = axis.raw.compensation.as_ref()?;
    let v = raw.verifies.as_ref()?;
    Some(case(axis, v, controller, files, settings))
}

fn case(
    axis: &AxisSpec,
    v: &crate::campaign::model::VerifiesRaw,
    controller: &dyn Controller,
    files: &Files,
    settings: &Settings,
) -> Result<VerifyCase, StatedTableError> {
    let kind = axis.raw.kind;
    let path = files
        .resolve(&v.before)
        .map_err(|refused| StatedTableError::Path {
            key: "compensation.verifies.before",
            refused,
        })?;
    let read = crate::measurement::read_file_within(&path, &Default::default(), Some(files))
        .map_err(|e| StatedTableError::Before(Box::new(e)))?;
    let (before, before_nde) = crate::campaign::stages::nde::apply(axis, read.data);
    let before_active = match &v.active {
        Some(a) => active(
            a,
            kind,
            controller,
            files,
            &settings.place,
            "compensation.verifies.active",
        )?,
        None => Active::default(),
    };
    // The verified table is the test's active one unless another is stated: read once.
    let stated = axis
        .raw
        .compensation
        .as_ref()
        .and_then(|c| c.active.as_ref());
    let table = match (
        stated,
        settings.active.as_ref().and_then(|a| a.table.clone()),
    ) {
        (None, Some(table)) => table,
        _ => {
            let at = TableFile::Stated {
                files,
                file: &v.table,
                key: "compensation.verifies.table",
            };
            read_table(at, controller, kind, settings.place.axis.as_deref())?
        }
    };
    let backlash = v.backlash_um.or(v.backlash_arcsec);
    let compared = compared_tables(&before_active, table, &v.table, backlash, controller, kind)?;
    Ok(VerifyCase {
        before,
        before_file: v.before.clone(),
        before_recognised: read.recognised,
        before_nde,
        old: compared.old,
        new: compared.new,
        controller: controller.name(),
        notes: compared.notes,
    })
}

/// The table loaded on another axis of the machine, read from `path` given by the option
/// `key` (the axis's own table from a file of several, else the file's only one), to tell
/// a table loaded on the wrong axis.
pub fn other_table(
    axis: &str,
    path: &Path,
    key: &'static str,
    controller: &dyn Controller,
    kind: AxisKind,
) -> Result<crate::verify::Other, StatedTableError> {
    let at = TableFile::Given { path, key };
    let table = read_table(at, controller, kind, Some(axis))
        .or_else(|_| read_table(at, controller, kind, None))?;
    Ok(crate::verify::Other {
        axis: axis.to_string(),
        new: table,
    })
}

/// The corrections a re-measurement is compared with, as the controller adds them.
#[derive(Debug, Clone)]
pub struct ComparedTables {
    /// Active during the measurement before (`None`: nothing was).
    pub old: Option<Table>,
    /// Loaded since.
    pub new: Table,
    /// What was assumed (an unstated backlash).
    pub notes: Vec<String>,
}

/// The correction active during the measurement before (`before`) and the one loaded since:
/// `table` from `file` with the backlash loaded with it; unstated, the backlash active
/// before, which a note says. The one composition for a campaign's `verifies:`, the command
/// `verify` and the Python package's.
pub fn compared_tables(
    before: &Active,
    table: Table,
    file: &str,
    backlash: Option<f64>,
    controller: &dyn Controller,
    kind: AxisKind,
) -> Result<ComparedTables, StatedTableError> {
    let mut notes = Vec::new();
    let mut loaded = Active {
        table: Some(table),
        file: Some(file.to_string()),
        backlash,
    };
    if loaded.backlash.is_none() && before.backlash.is_some() {
        loaded.backlash = before.backlash;
        notes.push(
            "the backlash loaded with the table was not stated: taken as the one active before"
                .into(),
        );
    }
    let rule = controller.backlash();
    let new = loaded.total(rule, kind).ok_or(StatedTableError::Empty)?;
    Ok(ComparedTables {
        old: before.total(rule, kind),
        new,
        notes,
    })
}

/// What a re-measurement that verifies a table is compared with, or why it cannot be.
pub type Case = Option<Result<Box<VerifyCase>, StatedTableError>>;

/// The compensation of a test by its machine's `controller` (none: no table), with the
/// warnings of its diagnosis (`diagnose` runs it when the run did not), and what its
/// re-measurement is compared with when it verifies a table.
pub(crate) fn for_test(
    controller: Option<&str>,
    axis: &AxisSpec,
    data: &AxisData,
    files: &Files,
    diagnosis: Option<&crate::diagnose::Diagnosis>,
    diagnose: impl FnOnce() -> crate::diagnose::Diagnosis,
) -> (Option<compensate::Compensation>, Case) {
    let Some(c) = controller.and_then(crate::compensate::controllers::find) else {
        return (None, None);
    };
    let file_type = axis
        .raw
        .compensation
        .as_ref()
        .and_then(|r| r.comp_file_type);
    // Checked when the campaign was loaded: only LinuxCNC's, 0 or 1.
    let c = crate::compensate::controllers::with_comp_file_type(c, file_type).unwrap_or(c);
    let own;
    let diagnosis = match diagnosis {
        Some(d) => d,
        None => {
            own = diagnose();
            &own
        }
    };
    let (compensation, case) = of_test(c, axis, data, files, diagnosis);
    (Some(compensation), case.map(|r| r.map(Box::new)))
}

/// The compensation of a test by `controller` as its axis states it, and what its
/// re-measurement is compared with when it verifies a table. A table file that cannot be
/// read leaves the compensation refused with the reason (the test is still judged).
pub(crate) fn of_test(
    controller: &dyn Controller,
    axis: &AxisSpec,
    data: &AxisData,
    files: &Files,
    diagnosis: &crate::diagnose::Diagnosis,
) -> (
    compensate::Compensation,
    Option<Result<VerifyCase, StatedTableError>>,
) {
    match settings(axis, controller, files) {
        Ok(s) => (
            compensate::compensation(controller, data, axis.standard, &s, diagnosis),
            verify_case(axis, controller, files, &s),
        ),
        Err(e) => {
            let verifies = axis
                .raw
                .compensation
                .as_ref()
                .is_some_and(|c| c.verifies.is_some());
            let refused = compensate::Compensation::refused(controller, &e.to_string());
            (refused, verifies.then_some(Err(e)))
        }
    }
}
