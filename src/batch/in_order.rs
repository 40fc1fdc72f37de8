//! [`in_order_until`](super::in_order_until) on rayon's pool: each thread
//! takes the next index in turn; the results are handed on in index order
//! as the ones before them arrive, and once the consumer has had enough,
//! no later index is started.

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

pub(super) fn in_order_until<R, G, Consume>(count: usize, f: G, consume: Consume)
where
    R: Send,
    G: Fn(usize) -> R + Send + Sync,
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
            let result = f(index);
            // (A thread that panicked poisons the lock; its panic is the
            // one the scope passes on.)
            let mut guard = handing.lock().unwrap_or_else(|e| e.into_inner());
            let h = &mut *guard;
            if h.done {
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
