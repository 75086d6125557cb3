//! axcheck's integration tests, in one test binary (as ripgrep keeps them): one link of
//! the library and its heavy dependencies instead of one per file.

mod common;
mod compensate;

mod active;
mod architecture;
mod bad_input;
mod big_input;
mod browser;
mod campaign;
mod catalogue;
mod certificate;
mod cli;
mod console;
mod controllers;
mod cross_tables;
mod decision;
mod diagnose;
mod ecmc_app;
mod external;
mod fuzz_corpus;
mod geometry;
mod geometry_campaign;
mod geometry_layouts;
mod gost27843;
mod history;
#[cfg(unix)]
mod hostile_fs;
mod injection;
mod instrument_calibration;
mod iso230_2;
mod languages;
mod layouts;
#[cfg(unix)]
mod linuxcnc_sim;
mod options;
mod outputs;
mod placeholders;
mod plan;
mod program_check;
mod programs;
mod properties;
mod renishaw;
mod report_compensation;
mod report_layout;
mod reports;
mod reproduce;
mod rules;
mod simulator;
mod standards;
mod summary_html;
mod surface;
mod trend;
mod uncertainty;
mod verdicts;
mod verify;
mod windows;
mod workbook;
