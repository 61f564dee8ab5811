//! Output buffers of batched calls.
//!
//! A large batch's outputs are fresh memory from the operating system (the allocator maps
//! blocks above a few MB on their own), and the first write to each 4 KiB page of it faults
//! into the kernel: for the Panda's `M` and `c + g` over 100,000 states (45 MB) the faults took
//! about a third of the batched call (`perf record` on `python/bench.py`'s call). On Linux,
//! buffers of at least [`HUGE_PAGES_FROM`] bytes are therefore marked for transparent huge
//! pages (`madvise(MADV_HUGEPAGE)`), so the kernel maps them 2 MiB at a time; where it declines
//! (huge pages off, or none free) nothing changes but the speed.

/// Buffers of at least this many bytes are offered huge pages (four of them).
pub const HUGE_PAGES_FROM: usize = 8 << 20;

/// The size of a transparent huge page on x86-64 and aarch64 Linux.
#[cfg(target_os = "linux")]
const HUGE_PAGE: usize = 2 << 20;

/// `len` zeros, in memory offered huge pages when the buffer is large (see the module).
pub fn zeros(len: usize) -> Vec<f64> {
    let v = vec![0.0; len];
    #[cfg(target_os = "linux")]
    if len * core::mem::size_of::<f64>() >= HUGE_PAGES_FROM {
        // The whole huge pages inside the buffer; the partial ones at its ends stay as they are.
        let start = (v.as_ptr() as usize).next_multiple_of(HUGE_PAGE);
        let end = (v.as_ptr() as usize + len * core::mem::size_of::<f64>()) / HUGE_PAGE * HUGE_PAGE;
        if end > start {
            // SAFETY: `start..end` lies inside `v`'s allocation, which stays alive and in place;
            // MADV_HUGEPAGE changes how the kernel backs the pages, never their contents (the
            // zeros already there stay zeros), and a refusal is only a return code.
            unsafe {
                libc::madvise(start as *mut libc::c_void, end - start, libc::MADV_HUGEPAGE);
            }
        }
    }
    v
}
