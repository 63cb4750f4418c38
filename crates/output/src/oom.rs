//! Out of memory without an abort: the process's allocator ([`ExitOnOom`], installed by the
//! `csgpix` binary) turns a failed allocation into the one-line error every refusal is, exit
//! status 2, with the staged outputs removed ([`crate::remove_all_staged`]), where Rust's
//! default would print `memory allocation of N bytes failed` and abort (SIGABRT, the staged
//! files left behind).
//!
//! The run's estimate is checked against `--max-memory` before it allocates
//! (docs/memory.md); this is the net under that check, for what an estimate cannot see
//! (another process taking the memory, an address-space limit the default did not leave
//! room for). The largest allocations are fallible instead ([`try_zeroed`]): inside
//! [`fallible`], a failed allocation returns null to its caller as the allocator API says,
//! so the caller's own error names what it was allocating.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

thread_local! {
    /// Depth of [`fallible`] scopes on this thread: above 0, a failed allocation is the
    /// caller's to handle. Const-initialised with no destructor, so the allocator may read it.
    static FALLIBLE: Cell<u32> = const { Cell::new(0) };
}

/// Run `f` with this thread's failed allocations returned to their callers (null, and so
/// `try_reserve`'s error) rather than ending the process.
pub fn fallible<T>(f: impl FnOnce() -> T) -> T {
    struct Scope;
    impl Drop for Scope {
        fn drop(&mut self) {
            FALLIBLE.with(|d| d.set(d.get() - 1));
        }
    }
    FALLIBLE.with(|d| d.set(d.get() + 1));
    let _scope = Scope;
    f()
}

/// Under an address-space limit (`ulimit -v`), one malloc arena for every thread. glibc
/// gives each new thread an arena of its own, reserving 64 MiB of address space for it (and
/// 128 MiB while it aligns it), and fails the thread's first allocation, however small, when
/// that reservation does not fit: 2 threads cost 200-400 MiB of a limit before the run
/// allocates anything. The run's own allocations are few and large, so one arena costs it
/// nothing measurable. Call from `main` before any thread starts; no effect without a limit
/// or outside glibc.
pub fn one_arena_under_address_limit() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    if rlimit(libc::RLIMIT_AS).is_some() {
        // SAFETY: mallopt(3) with a documented parameter, before any other thread exists.
        unsafe {
            libc::mallopt(libc::M_ARENA_MAX, 1);
        }
    }
}

/// An allocation that failed: how many bytes were asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("out of memory: {} MiB could not be allocated", .bytes.div_ceil(1 << 20))]
pub struct AllocFailed {
    /// The bytes asked for.
    pub bytes: usize,
}

/// `n` zero bytes, or [`AllocFailed`] when the system has no room for them. The pages are
/// the system's zeroed ones (calloc), as `vec![0u8; n]`'s are: untouched ones cost nothing.
pub fn try_zeroed(n: usize) -> Result<Vec<u8>, AllocFailed> {
    if n == 0 {
        return Ok(Vec::new());
    }
    let failed = AllocFailed { bytes: n };
    let layout = Layout::array::<u8>(n).map_err(|_| failed)?;
    // SAFETY: `layout` has a non-zero size. A non-null pointer from the global allocator for
    // `layout` (align 1, size n) is exactly what `Vec::<u8>::from_raw_parts(ptr, n, n)`
    // takes; its n bytes are initialised (zeroed).
    unsafe {
        let ptr = fallible(|| std::alloc::alloc_zeroed(layout));
        if ptr.is_null() {
            return Err(failed);
        }
        Ok(Vec::from_raw_parts(ptr, n, n))
    }
}

/// The system's allocator, ending the process with a one-line error (exit status 2, staged
/// outputs removed) when an allocation fails outside [`fallible`]. Install it in a binary:
///
/// ```ignore
/// #[global_allocator]
/// static ALLOC: csgpix_output::ExitOnOom = csgpix_output::ExitOnOom;
/// ```
pub struct ExitOnOom;

// SAFETY: every method forwards to `System` unchanged; a null result either goes back to the
// caller (inside `fallible`) or ends the process, never returning an invalid pointer.
unsafe impl GlobalAlloc for ExitOnOom {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        checked(System.alloc(layout), layout.size())
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        checked(System.alloc_zeroed(layout), layout.size())
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        checked(System.realloc(ptr, layout, new_size), new_size)
    }
}

/// `ptr`, unless it is null outside a [`fallible`] scope: then the process ends.
fn checked(ptr: *mut u8, size: usize) -> *mut u8 {
    if ptr.is_null() && FALLIBLE.with(|d| d.get()) == 0 {
        out_of_memory(size);
    }
    ptr
}

/// Remove the staged outputs, say so in one line, exit 2. Written for a process with no
/// memory to spare: the message is formatted on the stack and written with one `write(2)`.
fn out_of_memory(size: usize) -> ! {
    crate::remove_all_staged();
    let mut line = StackLine::default();
    let _ = std::fmt::Write::write_fmt(
        &mut line,
        format_args!(
            "csgpix: out of memory: an allocation of {} failed ({}); lower the run's \
             size (--res, --size) or --max-memory, or free memory\n",
            Bytes(size),
            Limits,
        ),
    );
    // SAFETY: write(2) of an initialised buffer to standard error; _exit(2) ends the process
    // without running anything that might allocate.
    unsafe {
        libc::write(2, line.buf.as_ptr().cast(), line.len);
        libc::_exit(2)
    }
}

/// A size as the message says it: bytes below a MiB, else MiB (rounded up).
struct Bytes(usize);

impl std::fmt::Display for Bytes {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.0 {
            n if n < 1 << 20 => write!(f, "{n} bytes"),
            n => write!(f, "{} MiB", n.div_ceil(1 << 20)),
        }
    }
}

/// The process's memory limits, as the message names them (read with getrlimit(2), which
/// does not allocate).
struct Limits;

impl std::fmt::Display for Limits {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mib = |b: u64| b >> 20;
        match (rlimit(libc::RLIMIT_AS), rlimit(libc::RLIMIT_DATA)) {
            (Some(a), _) => write!(f, "address-space limit {} MiB, ulimit -v", mib(a)),
            (None, Some(d)) => write!(f, "data limit {} MiB, ulimit -d", mib(d)),
            (None, None) => f.write_str("the memory the system would give"),
        }
    }
}

/// The soft limit of `resource` in bytes, None if unlimited.
pub(crate) fn rlimit(resource: libc::__rlimit_resource_t) -> Option<u64> {
    let mut r = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    // SAFETY: getrlimit(2) fills the struct it is given.
    let ok = unsafe { libc::getrlimit(resource, &mut r) } == 0;
    (ok && r.rlim_cur != libc::RLIM_INFINITY).then_some(r.rlim_cur)
}

/// A line formatted without allocating (cut at 256 bytes).
struct StackLine {
    buf: [u8; 256],
    len: usize,
}

impl Default for StackLine {
    fn default() -> Self {
        StackLine {
            buf: [0; 256],
            len: 0,
        }
    }
}

impl std::fmt::Write for StackLine {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let room = self.buf.len() - self.len;
        let n = s.len().min(room);
        self.buf[self.len..self.len + n].copy_from_slice(&s.as_bytes()[..n]);
        self.len += n;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zeroed_bytes_are_zero_and_an_impossible_size_fails() {
        let v = try_zeroed(1 << 20).unwrap();
        assert_eq!(v.len(), 1 << 20);
        assert!(v.iter().all(|&b| b == 0));
        assert_eq!(try_zeroed(0).unwrap().len(), 0);
        let e = try_zeroed(usize::MAX / 2).unwrap_err();
        assert_eq!(e.bytes, usize::MAX / 2);
        assert!(e.to_string().starts_with("out of memory: "), "{e}");
    }

    #[test]
    fn fallible_scopes_nest_and_end() {
        fallible(|| fallible(|| assert_eq!(FALLIBLE.with(|d| d.get()), 2)));
        assert_eq!(FALLIBLE.with(|d| d.get()), 0);
    }

    #[test]
    fn the_stack_line_cuts_long_text() {
        let mut l = StackLine::default();
        let long = "x".repeat(300);
        std::fmt::Write::write_str(&mut l, &long).unwrap();
        assert_eq!(l.len, 256);
    }
}
