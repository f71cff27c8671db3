//! The global allocator of release builds: mimalloc, called without its alignment path where
//! Rust asks for no more alignment than every mimalloc block has.
//!
//! The `mimalloc` crate hands every request to `mi_malloc_aligned` / `mi_realloc_aligned`,
//! which first check whether a free block happens to have the asked alignment. Nearly every
//! allocation of rtcdoc (strings, vectors of pointers and integers) asks for 8 bytes or less,
//! and every mimalloc block is aligned to at least 8 bytes (its sizes are multiples of the word
//! size, and a page's first block is aligned to 16), so those go straight to `mi_malloc` /
//! `mi_realloc`: 2–3 % fewer instructions in a build (see book/src/performance.md). Larger
//! alignments take mimalloc's aligned calls, as before.

use libmimalloc_sys as mi;
use std::alloc::{GlobalAlloc, Layout};
use std::ffi::c_void;

/// The alignment every mimalloc block has.
const MIN_ALIGN: usize = 8;

/// mimalloc, plain calls for alignments up to [`MIN_ALIGN`].
pub struct Mi;

/// A mimalloc call that allocates `size` bytes (`mi_malloc`, `mi_zalloc`).
type Plain = unsafe extern "C" fn(usize) -> *mut c_void;
/// A mimalloc call that allocates `size` bytes aligned to `alignment`.
type Aligned = unsafe extern "C" fn(usize, usize) -> *mut c_void;

/// `plain` for a layout whose alignment every block has, `aligned` otherwise.
///
/// # Safety
/// As [`GlobalAlloc::alloc`]: `layout` has a non-zero size.
#[inline(always)]
unsafe fn allocate(layout: Layout, plain: Plain, aligned: Aligned) -> *mut u8 {
    let p = if layout.align() <= MIN_ALIGN {
        unsafe { plain(layout.size()) }
    } else {
        unsafe { aligned(layout.size(), layout.align()) }
    };
    p as *mut u8
}

// SAFETY: each call goes to mimalloc, which returns blocks of at least the size asked for and
// aligned to at least `MIN_ALIGN` (the plain calls) or to the alignment asked for (the aligned
// calls); memory is freed by `mi_free`, which takes blocks of either kind.
unsafe impl GlobalAlloc for Mi {
    #[inline]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        unsafe { allocate(layout, mi::mi_malloc, mi::mi_malloc_aligned) }
    }

    #[inline]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        unsafe { allocate(layout, mi::mi_zalloc, mi::mi_zalloc_aligned) }
    }

    #[inline]
    unsafe fn dealloc(&self, ptr: *mut u8, _layout: Layout) {
        unsafe { mi::mi_free(ptr as *mut c_void) }
    }

    #[inline]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let ptr = ptr as *mut c_void;
        let p = if layout.align() <= MIN_ALIGN {
            unsafe { mi::mi_realloc(ptr, new_size) }
        } else {
            unsafe { mi::mi_realloc_aligned(ptr, new_size, layout.align()) }
        };
        p as *mut u8
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Blocks of every small size and alignment come back aligned as asked, hold what is
    /// written to them through a reallocation, and are freed.
    #[test]
    fn blocks_are_aligned_as_asked_and_keep_their_bytes() {
        for align in [1usize, 2, 4, 8, 16, 32, 64] {
            for size in [1usize, 3, 7, 8, 12, 24, 40, 100, 1000, 5000, 70_000] {
                let layout = Layout::from_size_align(size, align).expect("a valid layout");
                unsafe {
                    let p = Mi.alloc(layout);
                    assert!(!p.is_null());
                    assert_eq!(p as usize % align, 0, "size {size}, align {align}");
                    for i in 0..size {
                        *p.add(i) = (i % 251) as u8;
                    }
                    let q = Mi.realloc(p, layout, size * 3);
                    assert!(!q.is_null());
                    assert_eq!(q as usize % align, 0, "realloc: size {size}, align {align}");
                    for i in 0..size {
                        assert_eq!(*q.add(i), (i % 251) as u8);
                    }
                    Mi.dealloc(q, Layout::from_size_align(size * 3, align).expect("valid"));
                    let z = Mi.alloc_zeroed(layout);
                    assert_eq!(z as usize % align, 0);
                    assert!((0..size).all(|i| *z.add(i) == 0));
                    Mi.dealloc(z, layout);
                }
            }
        }
    }
}
