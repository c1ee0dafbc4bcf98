//! The worker threads a run renders on: not a slide's lesson. One pool for a whole run ([`on_workers`]),
//! each thread with a stack deep enough for the lesson's recursion ([`WORKER_STACK_SIZE`]); a count that
//! cannot start is refused naming its stacks ([`worker_stacks`]), which are what a limit on the address space
//! runs out of. The lesson re-exports them as `lecture6::lesson::render::{thread_pool, on_workers, ...}`.

use crate::files::error::{Error, Result};

/// How many nested `raytrace` calls a worker's stack has room for: the lesson's safety cap on the
/// recursion (`lecture6::lesson::scene::RECURSION_SAFETY_CAP` is this number).
pub const NESTED_CALLS: u32 = 1000;

/// Stack size of the worker threads: room for [`NESTED_CALLS`] nested `raytrace` calls at 8 KiB each. One
/// level of mirror reflection takes about 0.7 KiB (measured: a ray bouncing 1000 times between two mirrors
/// runs in 768 KiB of stack and overflows 640 KiB); the margin is for shaders with larger frames or more
/// nested calls per level. Only the pages a render touches are committed.
pub const WORKER_STACK_SIZE: usize = NESTED_CALLS as usize * 8 * 1024;

thread_local! {
    /// The `threads` asked of the [`thread_pool`] whose worker this thread is, if it is one.
    static WORKER_OF: std::cell::Cell<Option<Option<usize>>> = const { std::cell::Cell::new(None) };
}

/// The worker threads the renderer uses: `threads` of them, or one per core, each with a stack of
/// [`WORKER_STACK_SIZE`]. A refusal names the stacks: they are what a limit on the address space runs out of.
pub fn thread_pool(threads: Option<usize>) -> Result<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .stack_size(WORKER_STACK_SIZE)
        .start_handler(move |_| WORKER_OF.set(Some(threads)))
        .build()
        .map_err(|e| {
            let count = threads.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
            Error::parameter("thread count", count, format!("cannot start them ({e}): {}", worker_stacks(count)))
        })
}

/// What the stacks of `count` worker threads need, in words: each [`WORKER_STACK_SIZE`] of address space.
pub fn worker_stacks(count: usize) -> String {
    let mib = WORKER_STACK_SIZE as f64 / (1 << 20) as f64;
    format!(
        "each worker thread needs {mib:.1} MiB of address space for its stack (room for {NESTED_CALLS} nested \
         bounces, the recursion's safety cap), {:.1} GiB for {count}",
        count as f64 * mib / 1024.0
    )
}

/// Runs `work` on `threads` worker threads ([`thread_pool`]): on the pool the calling thread is a worker of,
/// if it was made for `threads` (one pool for a whole run: each of its threads holds a stack of
/// [`WORKER_STACK_SIZE`]), else on a new one. `work` is given the number of workers.
pub fn on_workers<R: Send>(threads: Option<usize>, work: impl FnOnce(usize) -> R + Send) -> Result<R> {
    if WORKER_OF.get() == Some(threads) {
        return Ok(work(rayon::current_num_threads()));
    }
    Ok(thread_pool(threads)?.install(|| work(rayon::current_num_threads())))
}
