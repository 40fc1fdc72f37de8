//! The threads the package's parallel work runs on: a rayon pool of this
//! process's own. rayon's global pool does not survive `fork` (the child
//! inherits it without its threads, and its first parallel call waits for
//! them forever), and Python forks — `multiprocessing`, executors, Dask's
//! workers — so each process that calls the package builds its pool
//! anew, and the parallel work — a synthesis's starts, a Monte Carlo
//! run's samples: the library's batches — runs in it
//! (`ThreadPool::install`, which they honour).

use crate::errors::Failure;
use rayon::{ThreadPool, ThreadPoolBuilder};
use std::sync::{Arc, Mutex, PoisonError};

/// The pool and the process that built it.
static POOL: Mutex<Option<(u32, Arc<ThreadPool>)>> = Mutex::new(None);

/// This process's pool (as many threads as `RAYON_NUM_THREADS` says, or
/// cores).
fn pool() -> Result<Arc<ThreadPool>, Failure> {
    let mut guard = POOL.lock().unwrap_or_else(PoisonError::into_inner);
    let process = std::process::id();
    if let Some((owner, pool)) = guard.as_ref()
        && *owner == process
    {
        return Ok(Arc::clone(pool));
    }
    let pool = Arc::new(
        ThreadPoolBuilder::new()
            .thread_name(|k| format!("linkage-{k}"))
            .build()
            .map_err(|e| Failure::BadInput(format!("cannot start the threads: {e}")))?,
    );
    // A parent's pool, inherited without its threads by a forked child,
    // is left alone: dropping it would signal threads that are not there.
    if let Some(inherited) = guard.replace((process, Arc::clone(&pool))) {
        std::mem::forget(inherited);
    }
    Ok(pool)
}

/// `work()` on this process's pool.
pub fn install<T: Send>(work: impl FnOnce() -> Result<T, Failure> + Send) -> Result<T, Failure> {
    pool()?.install(work)
}
