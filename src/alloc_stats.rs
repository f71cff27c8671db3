//! A counting global allocator for memory profiling (cargo feature `alloc-stats`).
//!
//! Wraps mimalloc (the allocator of release builds) and keeps the bytes currently allocated and
//! the most ever allocated at once, so that `RTCDOC_TIMING=1` can print, after each stage, how
//! much of the peak RSS is live heap and which stage raised it. The counters are relaxed
//! atomics: exact totals, at the cost of two atomic additions an allocation, which is why this
//! is a feature and not the default.
//!
//! `cargo build --release --features alloc-stats`, then `RTCDOC_TIMING=1 rtcdoc build DIR -q`.
//! For a per-call-site picture, build with `--features system-alloc` instead (the system
//! allocator, which heaptrack and valgrind's massif intercept).

use std::alloc::{GlobalAlloc, Layout};
use std::sync::atomic::{AtomicUsize, Ordering};

static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

/// mimalloc with byte counters.
pub struct Counting;

fn grew(n: usize) {
    let now = LIVE.fetch_add(n, Ordering::Relaxed) + n;
    PEAK.fetch_max(now, Ordering::Relaxed);
}

fn shrank(n: usize) {
    LIVE.fetch_sub(n, Ordering::Relaxed);
}

// SAFETY: every call is forwarded to mimalloc with the same arguments; the counters only
// observe the sizes.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { crate::allocator::Mi.alloc(layout) };
        if !p.is_null() {
            grew(layout.size());
        }
        p
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { crate::allocator::Mi.alloc_zeroed(layout) };
        if !p.is_null() {
            grew(layout.size());
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { crate::allocator::Mi.dealloc(ptr, layout) };
        shrank(layout.size());
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let p = unsafe { crate::allocator::Mi.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            shrank(layout.size());
            grew(new_size);
        }
        p
    }
}

/// Bytes allocated now.
pub fn live() -> usize {
    LIVE.load(Ordering::Relaxed)
}

/// The most bytes allocated at once so far.
pub fn peak() -> usize {
    PEAK.load(Ordering::Relaxed)
}

/// Starts a new peak from what is allocated now (to find the peak of one stage).
pub fn reset_peak() {
    PEAK.store(live(), Ordering::Relaxed);
}
