//! [`in_order_until`](super::in_order_until) on rayon's pool: each thread
//! takes the next index in turn; the results are handed on in index order
//! as the ones before them arrive, and once the consumer has had enough,
//! no later index is started and those running are told they are not
//! wanted.

use std::collections::BTreeMap;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// What the threads share: the next index to hand on, the results that
/// came before their turn, and the consumer.
struct Handing<R, Consume> {
    next: usize,
    early: BTreeMap<usize, R>,
    consume: Consume,
    done: bool,
}

/// Stops the run (no index started from then on, every running one told
/// it is not wanted) if dropped while its thread panics.
struct StopOnPanic<'a>(&'a AtomicUsize);

impl Drop for StopOnPanic<'_> {
    fn drop(&mut self) {
        if std::thread::panicking() {
            self.0.store(0, Ordering::Release);
        }
    }
}

pub(super) fn in_order_until<R, G, Consume>(count: usize, f: G, consume: Consume)
where
    R: Send,
    G: Fn(usize, &dyn Fn() -> bool) -> R + Send + Sync,
    Consume: FnMut(R) -> bool + Send,
{
    let next = AtomicUsize::new(0);
    // No index from `end` on is started.
    let end = AtomicUsize::new(count);
    let handing = Mutex::new(Handing {
        next: 0,
        early: BTreeMap::new(),
        consume,
        done: false,
    });
    let work = || {
        loop {
            let index = next.fetch_add(1, Ordering::Relaxed);
            if index >= end.load(Ordering::Acquire) {
                return;
            }
            let result = {
                // A job that panics stops the run: its result will never
                // come, so nothing after it could be handed on.
                let _stop = StopOnPanic(&end);
                f(index, &|| index < end.load(Ordering::Acquire))
            };
            // (A consumer that panicked poisons the lock; its panic is the
            // one the scope passes on, and nothing more is handed on.)
            let mut guard = handing.lock().unwrap_or_else(|e| e.into_inner());
            let _stop = StopOnPanic(&end);
            let h = &mut *guard;
            if h.done || end.load(Ordering::Acquire) == 0 {
                continue;
            }
            h.early.insert(index, result);
            while let Some(result) = h.early.remove(&h.next) {
                h.next += 1;
                if (h.consume)(result) {
                    h.done = true;
                    h.early.clear();
                    end.store(h.next, Ordering::Release);
                    break;
                }
            }
        }
    };
    let threads = rayon::current_num_threads().clamp(1, count.max(1));
    rayon::scope(|scope| {
        for _ in 1..threads {
            scope.spawn(|_| work());
        }
        work();
    });
}

#[cfg(test)]
mod tests {
    use super::in_order_until;
    use std::time::Duration;

    /// Indices that take uneven times (a later one often done first): the
    /// consumer sees 0, 1, 2, … without a gap and nothing after the one
    /// it stops at, on any number of threads.
    #[test]
    fn results_are_handed_on_in_order_up_to_the_stop_whatever_the_threads() {
        for threads in 1..=4 {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            for stop in [0, 1, 5, 17, 39] {
                let mut seen = Vec::new();
                pool.install(|| {
                    in_order_until(
                        40,
                        |i, _| {
                            std::thread::sleep(Duration::from_micros((i as u64 * 7919) % 13 * 50));
                            i
                        },
                        |i| {
                            seen.push(i);
                            i == stop
                        },
                    )
                });
                assert_eq!(seen, (0..=stop).collect::<Vec<_>>(), "{threads} threads");
            }
            // Never satisfied: every index, in order.
            let mut seen = Vec::new();
            pool.install(|| {
                in_order_until(
                    25,
                    |i, _| i * i,
                    |r| {
                        seen.push(r);
                        false
                    },
                )
            });
            assert_eq!(seen, (0..25).map(|i| i * i).collect::<Vec<_>>());
            // Nothing to run.
            pool.install(|| in_order_until(0, |i, _| i, |_| panic!("no index to hand on")));
        }
    }

    /// Once the consumer has had enough, a job still running at a later
    /// index is told it is not wanted (and may end early); one that is
    /// handed on never is.
    #[test]
    fn a_job_after_the_stop_is_told_it_is_not_wanted() {
        use std::sync::atomic::{AtomicBool, Ordering};
        use std::time::Instant;
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        let (told, second) = (AtomicBool::new(false), AtomicBool::new(false));
        let began = Instant::now();
        let mut seen = Vec::new();
        pool.install(|| {
            in_order_until(
                8,
                |i, wanted| {
                    if i == 0 {
                        // Index 0 ends only once the other thread runs index 1.
                        while !second.load(Ordering::Relaxed)
                            && began.elapsed() < Duration::from_secs(5)
                        {
                            std::thread::sleep(Duration::from_millis(1));
                        }
                        assert!(wanted());
                        return i;
                    }
                    second.store(true, Ordering::Relaxed);
                    while wanted() && began.elapsed() < Duration::from_secs(5) {
                        std::thread::sleep(Duration::from_millis(1));
                    }
                    told.fetch_or(!wanted(), Ordering::Relaxed);
                    i
                },
                |i| {
                    seen.push(i);
                    true
                },
            )
        });
        assert_eq!(seen, [0]);
        assert!(told.load(Ordering::Relaxed));
        assert!(began.elapsed() < Duration::from_secs(5));
    }

    /// A job that panics passes its panic on to the caller, soon: the
    /// jobs after it are not run to the end first.
    #[test]
    fn a_panicking_job_panics_the_caller() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        let began = std::time::Instant::now();
        let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            pool.install(|| {
                in_order_until(
                    10_000,
                    |i, _| {
                        assert!(i != 3, "job 3 fails");
                        std::thread::sleep(Duration::from_millis(1));
                        i
                    },
                    |_| false,
                )
            })
        }));
        assert!(caught.is_err());
        // (Run to the end, the 10 000 jobs of 1 ms would take 5 s.)
        assert!(
            began.elapsed() < Duration::from_secs(2),
            "{:?}",
            began.elapsed()
        );
    }
}
