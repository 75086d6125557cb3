//! Big inputs from the bad-input catalogue: a 200 MB file and 10 million rows. The readers
//! stream line by line (lines of at most 64 KiB) and stop at the first reading over
//! `MAX_READINGS`, so memory stays bounded whatever the file's size; a campaign holding
//! such a file next to a good axis still evaluates the good axis.
//!
//! The files are written streaming into a scratch folder, one test at a time (a lock), and
//! removed afterwards. Peak memory is measured in-process by a counting allocator around
//! the reader, which is exact and needs no timing.

use crate::common::{axcheck, data_path, scratch};
use axcheck::measurement::{self, MAX_READINGS};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::io::{BufWriter, Write};
use std::path::Path;
use std::sync::Mutex;

/// The system allocator, counting the bytes each thread has in use and their peak. Per
/// thread, because every integration test shares this binary and runs beside this one: the
/// reader under test runs on the test's own thread, so its thread's count is exactly its
/// own. (A block freed on another thread than the one that allocated it moves the counts
/// of both; the reader hands no memory to other threads.)
struct Counting;

thread_local! {
    static IN_USE: Cell<isize> = const { Cell::new(0) };
    static PEAK: Cell<isize> = const { Cell::new(0) };
}

fn grew(bytes: usize) {
    // `try_with`: a thread being torn down may still allocate after its counters are gone.
    let _ = IN_USE.try_with(|in_use| {
        let now = in_use.get() + bytes as isize;
        in_use.set(now);
        let _ = PEAK.try_with(|peak| peak.set(peak.get().max(now)));
    });
}

fn shrank(bytes: usize) {
    let _ = IN_USE.try_with(|in_use| in_use.set(in_use.get() - bytes as isize));
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged to the system allocator.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            grew(layout.size());
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged to the system allocator.
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            grew(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: forwarded unchanged to the system allocator.
        unsafe { System.dealloc(ptr, layout) };
        shrank(layout.size());
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: forwarded unchanged to the system allocator.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            shrank(layout.size());
            grew(new_size);
        }
        p
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// One big file at a time: keeps the disk use and the allocation peak to one test.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// Bytes this thread allocated at the peak while `f` runs, above what it had in use before.
fn peak_allocated<T>(f: impl FnOnce() -> T) -> (T, usize) {
    let before = IN_USE.with(Cell::get);
    PEAK.with(|peak| peak.set(before));
    let value = f();
    let peak = PEAK.with(Cell::get);
    (value, (peak - before).max(0) as usize)
}

const MB: usize = 1 << 20;
/// What reading a file may allocate at most: `MAX_READINGS` readings with a few
/// temperatures are about 20 MB; the file's own size never counts.
const MEMORY_LIMIT: usize = 64 * MB;

/// Writes a file streaming through a 1 MiB buffer; `rows(w)` writes the content.
fn write_streaming(path: &Path, rows: impl FnOnce(&mut dyn Write) -> std::io::Result<()>) {
    let file = std::fs::File::create(path).unwrap();
    let mut w = BufWriter::with_capacity(MB, file);
    rows(&mut w).unwrap();
    w.flush().unwrap();
}

/// A plausible positioning test row k: 200 targets, up then down, runs counting up.
fn row(k: usize) -> (usize, &'static str, usize) {
    let target = (k % 200) * 5;
    let direction = if (k / 200).is_multiple_of(2) {
        "up"
    } else {
        "down"
    };
    (target, direction, k / 400 + 1)
}

/// `axcheck eval FILE` fails with exit 2 and `message`; the reader called in-process
/// returns the same error while allocating less than [`MEMORY_LIMIT`].
fn assert_refused(path: &Path, message: &str) -> usize {
    let (code, _, stderr) = axcheck(&["eval", path.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains(message), "want `{message}` in: {stderr}");
    let (result, peak) = peak_allocated(|| measurement::read_file(path, None));
    let e = result.expect_err("the big file is refused");
    assert!(e.to_string().contains(message), "{e}");
    assert!(
        peak < MEMORY_LIMIT,
        "reading {} allocated {} MB at the peak (limit {} MB)",
        path.display(),
        peak / MB,
        MEMORY_LIMIT / MB
    );
    peak
}

/// A campaign with the ISO Table 2 file as a good axis and `big` as a second one:
/// `check` reports the good axis as passing and the big file as an error with `message`.
fn assert_campaign_still_evaluates(dir: &Path, big: &str, message: &str) {
    std::fs::copy(data_path("iso230-2_table2.csv"), dir.join("data/good.csv")).unwrap();
    let campaign = dir.join("campaign.yaml");
    std::fs::write(
        &campaign,
        format!(
            "campaign: {{name: Big, spec: general}}\nmachines:\n  - id: M\n    axes:\n      - {{name: GOOD, kind: linear, data: data/good.csv}}\n      - {{name: BIG, kind: linear, data: data/{big}}}\n"
        ),
    )
    .unwrap();
    let (code, stdout, stderr) = axcheck(&["check", campaign.to_str().unwrap()]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(
        stdout.contains("2 tests: 1 pass, 0 fail, 0 noncompliant, 1 error"),
        "{stdout}"
    );
    let line = stdout
        .lines()
        .find(|l| l.contains("M BIG"))
        .unwrap_or_else(|| panic!("no line for the big axis in {stdout}"));
    assert!(line.contains("ERROR") && line.contains(big), "{line}");
    assert!(line.contains(message), "want `{message}` in: {line}");
}

#[test]
fn a_200_mb_file_of_readings_stops_at_the_reading_limit() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let dir = scratch("big-200mb");
    let path = dir.join("data/big.csv");
    write_streaming(&path, |w| {
        writeln!(
            w,
            "target_mm,direction,run,deviation_um,time_s,temp_table_c,temp_screw_c,temp_air_c"
        )?;
        let mut written = 0;
        let mut k = 0;
        while written < 200 * MB {
            let (target, direction, run) = row(k);
            let line = format!(
                "{target}.000000,{direction},{run},{:.6},{:.3},20.123456,20.654321,21.000001\n",
                0.5 + (k % 7) as f64 * 0.01,
                k as f64 * 0.5
            );
            w.write_all(line.as_bytes())?;
            written += line.len();
            k += 1;
        }
        Ok(())
    });
    assert!(std::fs::metadata(&path).unwrap().len() >= 200 * MB as u64);
    let message = format!(
        "big.csv:{}: the file holds more than {MAX_READINGS} readings; split it into one file per test",
        MAX_READINGS + 2
    );
    let peak = assert_refused(&path, &message);
    eprintln!("200 MB of readings: {} MB allocated at the peak", peak / MB);
    assert_campaign_still_evaluates(&dir, "big.csv", &message);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn ten_million_rows_stop_at_the_reading_limit() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let dir = scratch("big-10m-rows");
    let path = dir.join("data/rows.csv");
    write_streaming(&path, |w| {
        writeln!(w, "# 10 million rows\ntarget_mm,direction,run,deviation_um")?;
        for k in 0..10_000_000 {
            let (target, direction, run) = row(k);
            writeln!(w, "{target},{direction},{run},0.5")?;
        }
        Ok(())
    });
    // Line 1 is the comment, 2 the header, readings from line 3.
    let message = format!(
        "rows.csv:{}: the file holds more than {MAX_READINGS} readings",
        MAX_READINGS + 3
    );
    let peak = assert_refused(&path, &message);
    eprintln!("10 million rows: {} MB allocated at the peak", peak / MB);
    assert_campaign_still_evaluates(&dir, "rows.csv", &message);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Comments do not count as readings, so this file is read to its end: 200 MB pass
/// through a 64 KiB line buffer and the reader ends with "no readings".
#[test]
fn a_200_mb_file_of_comments_is_read_to_its_end_in_bounded_memory() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let dir = scratch("big-comments");
    let path = dir.join("data/comments.csv");
    let comment = format!("# {}\n", "x".repeat(60 * 1024));
    write_streaming(&path, |w| {
        writeln!(w, "target_mm,direction,run,deviation_um")?;
        for _ in 0..(200 * MB).div_ceil(comment.len()) {
            w.write_all(comment.as_bytes())?;
        }
        Ok(())
    });
    let message = "comments.csv:1: the file has a header but no readings";
    assert_refused(&path, message);
    assert_campaign_still_evaluates(&dir, "comments.csv", message);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// 5 000 `temp_<name>_c` columns would keep 40 kB per reading (800 MB for a 200 MB
/// file): refused at the header, which names the column where the limit is passed.
#[test]
fn thousands_of_temperature_columns_are_refused_at_the_header() {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let dir = scratch("big-wide");
    let path = dir.join("data/wide.csv");
    let temps = 5000;
    let header = std::iter::once("target_mm,direction,run,deviation_um".to_string())
        .chain((0..temps).map(|t| format!("temp_s{t}_c")))
        .collect::<Vec<_>>()
        .join(",");
    let values = ",20".repeat(temps);
    write_streaming(&path, |w| {
        writeln!(w, "{header}")?;
        for k in 0..1000 {
            let (target, direction, run) = row(k);
            writeln!(w, "{target},{direction},{run},0.5{values}")?;
        }
        Ok(())
    });
    // The 65th temperature column starts after the 4 core columns and 64 `temp_sN_c,`.
    let column = header.find("temp_s64_c").unwrap() + 1;
    let message = format!(
        "wide.csv:1:{column}: more than {} temperature columns (temp_<name>_c); keep the sensors of this test, at most {}",
        measurement::MAX_TEMPERATURES,
        measurement::MAX_TEMPERATURES
    );
    assert_refused(&path, &message);
    assert_campaign_still_evaluates(&dir, "wide.csv", &message);
    std::fs::remove_dir_all(&dir).unwrap();
}
