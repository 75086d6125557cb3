//! What a measurement file says of its own test beyond the readings: who, where and when
//! (a Renishaw file's `USER-TEXT::`) and the environment (its `ENVIRONMENT::`). It
//! completes the campaign's report header and test conditions (ISO 230-2 clause 7.1)
//! where the campaign is silent; the campaign's own values always win.

use serde::Serialize;

/// The file's own account of its test.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct FileInfo {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub machine: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub serial: Option<String>,
    /// The test's date as the file writes it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub date: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub operator: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub axis: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub location: Option<String>,
    /// Air temperature at the start and end of the test, °C.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) air_temperature_start_c: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) air_temperature_end_c: Option<f64>,
    /// Mean air pressure over the test, kPa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub air_pressure_kpa: Option<f64>,
    /// Mean relative humidity over the test, %.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub air_humidity_pct: Option<f64>,
    /// The material (machine) temperature sensors fitted.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub(crate) material_sensors: Vec<MaterialReading>,
    /// The expansion coefficient the file was taken with, µm/(m·°C) (= ppm/°C).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub expansion_um_per_m_c: Option<f64>,
}

/// One material temperature sensor's readings at the start and end of the test, °C.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MaterialReading {
    pub name: String,
    pub start_c: Option<f64>,
    pub end_c: Option<f64>,
}

impl FileInfo {
    /// Whether the file said anything at all.
    pub fn is_empty(&self) -> bool {
        *self == FileInfo::default()
    }
}
