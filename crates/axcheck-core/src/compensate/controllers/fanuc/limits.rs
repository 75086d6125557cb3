//! The numbers of FANUC's pitch error compensation that the writer and the reader share:
//! the point numbers, the value range, the detection unit and the punch format.

/// Pitch error point numbers 0…1023, shared by all axes of the control \[recalled\].
pub(super) const PITCH_NUMBERS: usize = 1024;
/// Points per direction: two tables share the numbers.
pub(super) const MAX_POINTS: usize = PITCH_NUMBERS / 2;
/// One value per point: FOCAS `IODBPI.data` is a signed byte.
pub(super) const MIN_VALUE: i64 = -128;
pub(super) const MAX_VALUE: i64 = 127;
/// Magnification 3623: 1…100 (0 acts as 1) \[recalled\].
pub(super) const MAX_MAGNIFICATION: i64 = 100;
/// 3627 is a word.
pub(super) const MAX_WORD: i64 = i16::MAX as i64;
/// The detection unit assumed: 1 µm, 0.001° = 3.6″.
pub(super) const DETECTION_UM: f64 = 1.0;
pub(super) const DETECTION_ARCSEC: f64 = 3.6;
/// Parameters 3624/3625 in 0.001 mm or 0.001°.
pub(super) const PER_POSITION_UNIT: f64 = 1000.0;
/// Punch format: N = 10000 + point number \[recalled\].
pub(super) const PUNCH_BASE: usize = 10000;
