//! The firmware for QEMU's mps2-an386 board (Cortex-M4F): cortex-m-rt starts it, a 1 MiB
//! heap from embedded-alloc serves `alloc`, semihosting carries the output to the host's
//! terminal and the exit status to QEMU. It runs [`fisst_cortex_m::run`] and then reports, on
//! stderr, the peak heap and stack it used.

use core::fmt::Write;
use core::mem::MaybeUninit;
use cortex_m_rt::{ExceptionFrame, entry, exception};
use cortex_m_semihosting::{debug, hio};
use embedded_alloc::LlffHeap;
use fisst_cortex_m::PeakAlloc;

/// The heap's size in bytes.
const HEAP_SIZE: usize = 1024 * 1024;

/// The allocator behind `alloc` (`Vec`, `Box`, …), counting its peak use.
#[global_allocator]
static HEAP: PeakAlloc<LlffHeap> = PeakAlloc::new(LlffHeap::empty());

#[entry]
fn main() -> ! {
    // SAFETY: called once, first, with nothing on the stack below this frame.
    unsafe { stack::paint() };
    {
        static mut HEAP_MEM: [MaybeUninit<u8>; HEAP_SIZE] = [MaybeUninit::uninit(); HEAP_SIZE];
        // SAFETY: called once, before any allocation, with memory used for nothing else.
        unsafe { HEAP.inner().init(&raw mut HEAP_MEM as usize, HEAP_SIZE) }
    }

    let Ok(mut out) = hio::hstdout() else {
        exit(false)
    };
    let result = fisst_cortex_m::run(&mut out);
    let Ok(mut err) = hio::hstderr() else {
        exit(false)
    };
    let ok = match result {
        Ok(()) => true,
        Err(e) => {
            let _ = writeln!(err, "error: {e}");
            false
        }
    };
    // SAFETY: the stack was painted at the start.
    let stack = unsafe { stack::used() };
    let _ = writeln!(err, "heap peak: {} bytes of {HEAP_SIZE}", HEAP.peak());
    let _ = writeln!(err, "stack peak: {stack} bytes");
    exit(ok)
}

/// Ends the program: QEMU exits with status 0 if `ok`, else 1.
fn exit(ok: bool) -> ! {
    debug::exit(if ok {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    // Not reached under QEMU; on a board without a debugger attached, sleep.
    loop {
        cortex_m::asm::wfi();
    }
}

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    if let Ok(mut err) = hio::hstderr() {
        let _ = writeln!(err, "panic: {info}");
    }
    exit(false)
}

#[exception]
unsafe fn HardFault(frame: &ExceptionFrame) -> ! {
    if let Ok(mut err) = hio::hstderr() {
        let _ = writeln!(err, "hard fault: {frame:?}");
    }
    exit(false)
}

/// The stack's high-water mark: the free stack is filled with a pattern at start, and after
/// the run the lowest word that no longer holds it marks the deepest the stack went.
mod stack {
    /// The fill pattern.
    const PAINT: u32 = 0xdead_beef;
    /// Bytes below the stack pointer left alone while painting (the painting code's own calls).
    const MARGIN: usize = 1024;

    unsafe extern "C" {
        /// Top of the stack (cortex-m-rt: the end of RAM); the stack grows down from here.
        static _stack_start: u32;
        /// The lowest address the stack may reach (cortex-m-rt: the end of .bss and .uninit).
        static _stack_end: u32;
    }

    /// Fills the stack below the current stack pointer (less a margin) with `PAINT`.
    ///
    /// # Safety
    /// Nothing may live on the stack below the caller's frame.
    pub unsafe fn paint() {
        let sp = cortex_m::register::msp::read() as usize;
        let mut p = &raw const _stack_end as *mut u32;
        while (p as usize) < sp - MARGIN {
            // SAFETY: the word is in RAM, between the end of the statics and the stack pointer.
            unsafe {
                p.write_volatile(PAINT);
                p = p.add(1);
            }
        }
    }

    /// The bytes of stack used since [`paint`] (from its top to the lowest overwritten word).
    ///
    /// # Safety
    /// [`paint`] must have been called.
    pub unsafe fn used() -> usize {
        let top = &raw const _stack_start as usize;
        let mut p = &raw const _stack_end;
        // SAFETY: reads RAM between the end of the statics and the top of the stack.
        while (p as usize) < top && unsafe { p.read_volatile() } == PAINT {
            p = unsafe { p.add(1) };
        }
        top - p as usize
    }
}
