//! A global allocator wrapper that counts the bytes in use and remembers the peak, to measure
//! how much heap a computation needs (the firmware prints the peak after [`crate::run`]).

use core::alloc::{GlobalAlloc, Layout};
use core::sync::atomic::{AtomicUsize, Ordering};

/// Wraps an allocator `A`, counting the bytes requested and not yet freed.
pub struct PeakAlloc<A> {
    inner: A,
    in_use: AtomicUsize,
    peak: AtomicUsize,
}

impl<A> PeakAlloc<A> {
    /// Wraps `inner`; usable in a `static` (`#[global_allocator]`).
    pub const fn new(inner: A) -> Self {
        PeakAlloc {
            inner,
            in_use: AtomicUsize::new(0),
            peak: AtomicUsize::new(0),
        }
    }

    /// The wrapped allocator (e.g. to initialise its heap).
    pub fn inner(&self) -> &A {
        &self.inner
    }

    /// The most bytes in use at any time so far (requested sizes, without the allocator's
    /// own bookkeeping and alignment padding).
    pub fn peak(&self) -> usize {
        self.peak.load(Ordering::Relaxed)
    }
}

// SAFETY: every call is passed to `inner` unchanged; only the counters are added.
unsafe impl<A: GlobalAlloc> GlobalAlloc for PeakAlloc<A> {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's guarantees on `layout` are passed on.
        let p = unsafe { self.inner.alloc(layout) };
        if !p.is_null() {
            let now = self.in_use.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            self.peak.fetch_max(now, Ordering::Relaxed);
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` came from `alloc` above with this `layout`.
        unsafe { self.inner.dealloc(ptr, layout) };
        self.in_use.fetch_sub(layout.size(), Ordering::Relaxed);
    }
    // `realloc` keeps the default (alloc, copy, dealloc), so the peak counts both blocks.
}
