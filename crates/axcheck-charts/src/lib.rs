//! axcheck's charts as data, below the documents that show them: the chart kit
//! ([`chart_kit`]: a canvas that records what plotters draws, the scene it makes, its
//! labels), one file per chart ([`charts`]), and what each report reads ([`data`]). The PDF
//! reports typeset these scenes with Typst, `summary.html` draws the same scenes in the
//! browser: neither is needed to build them (no Typst, no polars here).

// The documentation is for the developers of this workspace and is built with its
// private items (`cargo doc --document-private-items`), where a public item's doc may
// link to the private item it is built on.
#![allow(rustdoc::private_intra_doc_links)]

pub mod chart_kit;
pub mod charts;
pub mod data;
pub mod figures;
pub mod words;

use axcheck_campaign::{campaign, inputs, judge, measurement, one_file, results, trend};
use axcheck_core::{
    axis_model, compensate, crosscheck, diagnose, evaluate, geometry, lang, nde, param_key, rules,
    uncertainty, units, verify,
};
