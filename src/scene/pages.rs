//! Memory the system may back with huge pages: the buffers and a large
//! scene's polygons are read in an order of their own (tile by tile), and
//! with 4 KiB pages each polygon or tile row a page apart also waits for
//! the processor to find its page.

/// A huge page (x86-64 and most others).
pub(crate) const HUGE_PAGE: usize = 2 << 20;

/// An ordinary page (x86-64 and most others).
pub(crate) const PAGE: usize = 4096;

/// Asks Linux to back the `bytes` of memory from `memory`, which belong to
/// one allocation and have not been written, with 2 MiB pages where it can.
#[cfg(target_os = "linux")]
pub(crate) fn advise_huge_pages(memory: *mut u8, bytes: usize) {
    let start = memory as usize;
    if bytes < 2 * HUGE_PAGE {
        return;
    }
    // madvise wants a page-aligned start: the whole pages inside the block.
    let aligned = start.next_multiple_of(PAGE);
    let length = (start + bytes - aligned) / PAGE * PAGE;
    // SAFETY: the range lies inside an allocation a vector owns, which it has
    // not written; MADV_HUGEPAGE only advises how to back it and changes no
    // contents. A refusal (no huge pages on this system) leaves it as it was,
    // so the result is ignored.
    unsafe {
        libc::madvise(aligned as *mut libc::c_void, length, libc::MADV_HUGEPAGE);
    }
}

#[cfg(not(target_os = "linux"))]
pub(crate) fn advise_huge_pages(_memory: *mut u8, _bytes: usize) {}

/// A vector with room for `length` items in memory offered huge pages before
/// anything is written to it (so that its first writes take huge pages).
pub(crate) fn with_huge_pages<T>(length: usize) -> Vec<T> {
    let mut room = Vec::with_capacity(length);
    let untouched = room.spare_capacity_mut();
    advise_huge_pages(untouched.as_mut_ptr().cast(), std::mem::size_of_val(untouched));
    room
}
