//! axcheck's campaigns: everything between the user's files and the core's stages, in the
//! pipeline's order — [`files`] (every user file read beneath its campaign's root, no
//! link out), [`campaign`] (the campaign file loaded, validated and its data files
//! resolved), [`inputs`] (what a run read, with each file's SHA-256), [`judge`] (acceptance specs read, limits taken from one), [`plan`] (the
//! plan file) and [`measurement`] (the readers, one file per layout) → [`batch`] runs
//! every axis through the core's stages in parallel → [`results`], the result model that
//! exporters, reports and the history read; [`one_file`] is the JSON of the commands that
//! take one measurement file. Beside them: [`simulate`] (simulation files
//! and synthetic fleets), [`trend`]'s tables, [`yaml`] (located YAML errors), [`atomic`]
//! and [`lock`] (outputs written whole, one run per folder), [`safe_text`] and [`panics`].
//!
//! It draws no page and writes no Parquet; the core's modules are named here as
//! `crate::evaluate` and the like through the private imports below.

// The documentation is for the developers of this workspace and is built with its
// private items (`cargo doc --document-private-items`), where a public item's doc may
// link to the private item it is built on.
#![allow(rustdoc::private_intra_doc_links)]

pub mod atomic;
pub mod batch;
pub mod campaign;
pub mod files;
pub mod history;
pub mod inputs;
pub mod judge;
pub mod lock;
pub mod measurement;
pub mod one_file;
pub mod panics;
pub mod plan;
pub mod results;
pub mod safe_text;
pub mod simulate;
pub mod table;
pub mod trend;
pub mod yaml;

use axcheck_core::{
    axis_model, compensate, crosscheck, diagnose, evaluate, geometry, lang, nde, param_key, rules,
    suggest, uncertainty, units, verify,
};
