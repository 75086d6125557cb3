//! The one worker pool of the outputs: a few threads that each take the next item as soon
//! as they are free (no chunks, so no thread waits for a slow neighbour), results kept in
//! the items' order, and the first error stops the others.

use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// Runs `task` on every item with up to `threads` scoped threads and returns the results
/// in the items' order. After the first error no new item is started and that error is
/// returned. `around` runs each thread's loop (called with the thread's index, from 0, and
/// the loop), e.g. inside a thread pool of its own, and may fail to (then its error is
/// returned); a panic in a task is raised again here.
pub(crate) fn map_in_order<T, R, E>(
    items: &[T],
    threads: usize,
    around: impl Fn(usize, &(dyn Fn() + Sync)) -> Result<(), E> + Sync,
    task: impl Fn(&T) -> Result<R, E> + Sync,
) -> Result<Vec<R>, E>
where
    T: Sync,
    R: Send,
    E: Send,
{
    let next = AtomicUsize::new(0);
    let failed = AtomicBool::new(false);
    let done: Mutex<Vec<(usize, Result<R, E>)>> = Mutex::new(Vec::with_capacity(items.len()));
    let work = || {
        while !failed.load(Ordering::Relaxed) {
            let index = next.fetch_add(1, Ordering::Relaxed);
            let Some(item) = items.get(index) else { break };
            let result = task(item);
            failed.fetch_or(result.is_err(), Ordering::Relaxed);
            done.lock()
                .unwrap_or_else(|p| p.into_inner())
                .push((index, result));
        }
    };
    let started: Result<(), E> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads.clamp(1, items.len().max(1)))
            .map(|thread| {
                let (around, work) = (&around, &work);
                scope.spawn(move || around(thread, work))
            })
            .collect();
        let mut started = Ok(());
        for handle in handles {
            match handle.join() {
                Ok(result) => started = started.and(result),
                Err(panic) => std::panic::resume_unwind(panic),
            }
        }
        started
    });
    started?;
    let mut done = done.into_inner().unwrap_or_else(|p| p.into_inner());
    done.sort_by_key(|(index, _)| *index);
    if let Some(position) = done.iter().position(|(_, r)| r.is_err()) {
        let (_, first_error) = done.swap_remove(position);
        return first_error.map(|_| Vec::new());
    }
    Ok(done.into_iter().filter_map(|(_, r)| r.ok()).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run<E>(_thread: usize, work: &(dyn Fn() + Sync)) -> Result<(), E> {
        work();
        Ok(())
    }

    #[test]
    fn results_come_in_order() {
        let items: Vec<u32> = (0..100).collect();
        let out: Result<Vec<u32>, ()> = map_in_order(&items, 3, run, |x| Ok(x * 2));
        assert_eq!(out.unwrap(), (0..100).map(|x| x * 2).collect::<Vec<_>>());
    }

    #[test]
    fn the_first_error_is_returned_and_stops_the_rest() {
        let items: Vec<u32> = (0..1000).collect();
        let started = AtomicUsize::new(0);
        let out: Result<Vec<u32>, u32> = map_in_order(&items, 1, run, |&x| {
            started.fetch_add(1, Ordering::Relaxed);
            if x >= 10 { Err(x) } else { Ok(x) }
        });
        assert_eq!(out, Err(10));
        assert_eq!(
            started.load(Ordering::Relaxed),
            11,
            "nothing started after the error"
        );
    }

    #[test]
    fn no_items_no_work() {
        let out: Result<Vec<u32>, ()> = map_in_order(&[] as &[u32], 4, run, |x| Ok(*x));
        assert_eq!(out.unwrap(), Vec::<u32>::new());
    }
}
