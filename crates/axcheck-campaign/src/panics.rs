//! Third-party readers that panic on damaged input, contained: a damaged file in a shared
//! folder is an error naming that file, not a crash of the whole run.
//!
//! Our own readers return errors; this is only for crates that do not (polars' Parquet
//! reader panics on some damaged footers). The panic's message is kept for the error and,
//! with [`install_quiet_hook`], not printed as a crash report.

use std::cell::Cell;
use std::panic::{self, AssertUnwindSafe};
use std::sync::Once;

thread_local! {
    /// Set while this thread runs a [`contained`] call.
    static CONTAINED: Cell<bool> = const { Cell::new(false) };
}

/// Runs `f`; a panic inside it becomes `Err` with the panic's message.
pub fn contained<T>(f: impl FnOnce() -> T) -> Result<T, Panicked> {
    let outer = CONTAINED.with(|c| c.replace(true));
    let result = panic::catch_unwind(AssertUnwindSafe(f));
    CONTAINED.with(|c| c.set(outer));
    result.map_err(|payload| Panicked {
        message: payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic without a message".to_string()),
    })
}

/// A panic [`contained`]: a library's own check that failed on a damaged file.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct Panicked {
    /// The panic's message, as the library wrote it.
    pub message: String,
}

/// Keeps the default panic report for every panic except those [`contained`] turns into
/// errors (called once by the command line; a library leaves the hook to its program).
pub fn install_quiet_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let default = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if !CONTAINED.with(Cell::get) {
                default(info);
            }
        }));
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_becomes_its_message() {
        install_quiet_hook();
        assert_eq!(contained(|| 7), Ok(7));
        let e = contained(|| -> u8 { panic!("footer length {} out of range", 12) });
        assert_eq!(
            e.map_err(|p| p.message),
            Err("footer length 12 out of range".to_string())
        );
        let e = contained(|| -> u8 { std::panic::panic_any(3_u8) });
        assert_eq!(
            e.map_err(|p| p.message),
            Err("a panic without a message".to_string())
        );
        // Nested: the outer call is still contained after the inner one ends.
        let e = contained(|| {
            let _ = contained(|| panic!("inner"));
            panic!("outer")
        });
        assert_eq!(e.map_err(|p| p.message), Err::<(), _>("outer".to_string()));
        assert!(!CONTAINED.with(Cell::get));
    }
}
