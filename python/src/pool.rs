//! The thread pool of this process, made again after a `fork`: a child forked from a process
//! whose pool had started (a `ProcessPoolExecutor` on Linux) inherits the pool's state but not
//! its threads, and rayon's global pool would wait on them for ever.

use std::sync::{Arc, Mutex};

use rayon::ThreadPool;

static POOL: Mutex<Option<(u32, Arc<ThreadPool>)>> = Mutex::new(None);

/// This process's pool (one thread per core), built on first use in each process.
///
/// # Errors
///
/// If the pool's threads cannot be started.
pub fn pool() -> Result<Arc<ThreadPool>, String> {
    let pid = std::process::id();
    let mut slot = POOL
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Some((owner, pool)) = slot.as_ref() {
        if *owner == pid {
            return Ok(Arc::clone(pool));
        }
        // Forked: the inherited pool has no threads; forget it without running its drop,
        // which would signal threads that do not exist here.
        if let Some((_, stale)) = slot.take() {
            std::mem::forget(stale);
        }
    }
    let pool = Arc::new(
        rayon::ThreadPoolBuilder::new()
            .build()
            .map_err(|e| format!("cannot start the thread pool: {e}"))?,
    );
    *slot = Some((pid, Arc::clone(&pool)));
    Ok(pool)
}
