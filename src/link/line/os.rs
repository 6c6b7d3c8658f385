//! The serial ioctls serialport does not make: the low-latency flag (`TIOCGSERIAL`/`TIOCSSERIAL`),
//! the kernel's RS-485 mode (`TIOCSRS485`), the driver's counters (`TIOCGICOUNT`), `HUPCL`, and
//! `tcdrain`. Linux only; elsewhere every call says it is not available and the line works
//! without. The structures are the kernel's (include/uapi/linux/serial.h, asm-generic/ioctls.h),
//! which libc does not define.

use super::{Counters, ModemLines, Rs485};

/// Why a call did not work: the OS error.
pub(in crate::link) type OsResult<T> = std::io::Result<T>;

#[cfg(target_os = "linux")]
pub(in crate::link) use linux::{Os, Saved};

#[cfg(not(target_os = "linux"))]
pub(in crate::link) use elsewhere::{Os, Saved};

#[cfg(target_os = "linux")]
mod linux {
    use std::os::fd::RawFd;

    use super::{Counters, ModemLines, OsResult, Rs485};

    /// `ASYNC_LOW_LATENCY` (`1 << ASYNCB_LOW_LATENCY`, 13).
    const ASYNC_LOW_LATENCY: libc::c_int = 1 << 13;

    /// `struct serial_struct`.
    #[repr(C)]
    #[derive(Default)]
    struct SerialStruct {
        kind: libc::c_int,
        line: libc::c_int,
        port: libc::c_uint,
        irq: libc::c_int,
        flags: libc::c_int,
        xmit_fifo_size: libc::c_int,
        custom_divisor: libc::c_int,
        baud_base: libc::c_int,
        close_delay: libc::c_ushort,
        io_type: libc::c_char,
        reserved_char: libc::c_char,
        hub6: libc::c_int,
        closing_wait: libc::c_ushort,
        closing_wait2: libc::c_ushort,
        iomem_base: usize,
        iomem_reg_shift: libc::c_ushort,
        port_high: libc::c_uint,
        iomap_base: libc::c_ulong,
    }

    /// The driver's RS-485 settings as found.
    #[derive(Debug, Clone, Copy)]
    pub(in crate::link) struct Saved(SerialRs485);

    /// `struct serial_rs485`.
    #[repr(C)]
    #[derive(Debug, Default, Clone, Copy)]
    struct SerialRs485 {
        flags: u32,
        delay_rts_before_send: u32,
        delay_rts_after_send: u32,
        padding: [u32; 5],
    }

    /// `struct serial_icounter_struct`.
    #[repr(C)]
    #[derive(Default)]
    struct Icounter {
        cts: libc::c_int,
        dsr: libc::c_int,
        rng: libc::c_int,
        dcd: libc::c_int,
        rx: libc::c_int,
        tx: libc::c_int,
        frame: libc::c_int,
        overrun: libc::c_int,
        parity: libc::c_int,
        brk: libc::c_int,
        buf_overrun: libc::c_int,
        reserved: [libc::c_int; 9],
    }

    /// The calls on one open port.
    #[derive(Debug, Clone, Copy)]
    pub(in crate::link) struct Os {
        fd: RawFd,
    }

    impl Os {
        /// The calls on `fd`, which the caller keeps open while it uses them.
        pub(in crate::link) fn new(fd: RawFd) -> Os {
            Os { fd }
        }

        /// `ioctl(fd, request, arg)`, and the OS error when it fails.
        fn ioctl<T>(&self, request: libc::Ioctl, arg: *mut T) -> OsResult<()> {
            // SAFETY: `fd` is an open descriptor the caller owns, and `arg` points to a value
            // of the kernel's structure for `request`, alive for the call.
            let rc = unsafe { libc::ioctl(self.fd, request, arg) };
            if rc < 0 {
                Err(std::io::Error::last_os_error())
            } else {
                Ok(())
            }
        }

        /// Sets the low-latency flag (what the driver does with it is the driver's).
        pub(in crate::link) fn set_low_latency(&self) -> OsResult<()> {
            let mut serial = SerialStruct::default();
            self.ioctl(libc::TIOCGSERIAL, &mut serial)?;
            serial.flags |= ASYNC_LOW_LATENCY;
            self.ioctl(libc::TIOCSSERIAL, &mut serial)
        }

        /// The modem lines (`TIOCMGET`).
        pub(in crate::link) fn modem_lines(&self) -> OsResult<ModemLines> {
            let mut bits: libc::c_int = 0;
            self.ioctl(libc::TIOCMGET, &mut bits)?;
            let on = |bit: libc::c_int| bits & bit != 0;
            Ok(ModemLines {
                dtr: on(libc::TIOCM_DTR),
                rts: on(libc::TIOCM_RTS),
                cts: on(libc::TIOCM_CTS),
                dsr: on(libc::TIOCM_DSR),
                cd: on(libc::TIOCM_CD),
            })
        }

        /// The driver's RS-485 settings now, to put back on closing.
        pub(in crate::link) fn rs485_saved(&self) -> Option<Saved> {
            let mut rs485 = SerialRs485::default();
            self.ioctl(libc::TIOCGRS485, &mut rs485).ok()?;
            Some(Saved(rs485))
        }

        /// Puts back RS-485 settings saved before.
        pub(in crate::link) fn restore_rs485(&self, saved: &Saved) -> OsResult<()> {
            let mut rs485 = SerialRs485 { ..saved.0 };
            self.ioctl(libc::TIOCSRS485, &mut rs485)
        }

        /// Puts the driver in RS-485 mode.
        pub(in crate::link) fn set_rs485(&self, mode: &Rs485) -> OsResult<()> {
            let (before, after) = mode.kernel_delays();
            let mut rs485 = SerialRs485 {
                flags: mode.kernel_flags(),
                delay_rts_before_send: before,
                delay_rts_after_send: after,
                padding: [0; 5],
            };
            self.ioctl(libc::TIOCSRS485, &mut rs485)
        }

        /// The driver's counters.
        pub(in crate::link) fn counters(&self) -> OsResult<Counters> {
            let mut c = Icounter::default();
            self.ioctl(libc::TIOCGICOUNT, &mut c)?;
            let n = |v: libc::c_int| u64::try_from(v).unwrap_or(0);
            Ok(Counters {
                rx: n(c.rx),
                tx: n(c.tx),
                frame: n(c.frame),
                overrun: n(c.overrun),
                parity: n(c.parity),
                brk: n(c.brk),
                buf_overrun: n(c.buf_overrun),
            })
        }

        /// Clears `HUPCL`: closing the port leaves DTR and RTS as they are.
        pub(in crate::link) fn keep_lines_on_close(&self) -> OsResult<()> {
            let mut termios = std::mem::MaybeUninit::<libc::termios>::uninit();
            // SAFETY: tcgetattr fills the termios it is given; it is read only on success.
            if unsafe { libc::tcgetattr(self.fd, termios.as_mut_ptr()) } < 0 {
                return Err(std::io::Error::last_os_error());
            }
            // SAFETY: initialised by the successful tcgetattr above.
            let mut termios = unsafe { termios.assume_init() };
            termios.c_cflag &= !libc::HUPCL;
            // SAFETY: a termios read from this descriptor, changed in one flag.
            if unsafe { libc::tcsetattr(self.fd, libc::TCSANOW, &termios) } < 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        }

        /// Waits until everything written has left the UART.
        pub(in crate::link) fn drain(&self) -> OsResult<()> {
            // SAFETY: a plain call on an open descriptor.
            if unsafe { libc::tcdrain(self.fd) } < 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        }
    }

    #[cfg(test)]
    mod tests {
        use super::*;

        #[test]
        fn the_structures_have_the_kernels_sizes() {
            assert_eq!(std::mem::size_of::<SerialRs485>(), 32);
            assert_eq!(std::mem::size_of::<Icounter>(), 80);
            #[cfg(target_pointer_width = "64")]
            assert_eq!(std::mem::size_of::<SerialStruct>(), 72);
        }

        #[test]
        fn a_file_is_no_serial_port() {
            let null = std::fs::File::open("/dev/null").unwrap();
            let os = Os::new(std::os::fd::AsRawFd::as_raw_fd(&null));
            assert!(os.set_low_latency().is_err());
            assert!(os.set_rs485(&Rs485::default()).is_err());
            assert!(os.counters().is_err());
        }
    }
}

#[cfg(not(target_os = "linux"))]
mod elsewhere {
    use super::{Counters, ModemLines, OsResult, Rs485};

    /// What every call answers here.
    fn not_here() -> std::io::Error {
        std::io::Error::new(
            std::io::ErrorKind::Unsupported,
            "not available on this system",
        )
    }

    /// The calls, none of which this system has here.
    #[derive(Debug, Clone, Copy)]
    pub(in crate::link) struct Os;

    /// RS-485 settings, which this system has none of here.
    #[derive(Debug, Clone, Copy)]
    pub(in crate::link) struct Saved;

    impl Os {
        pub(in crate::link) fn rs485_saved(&self) -> Option<Saved> {
            None
        }

        pub(in crate::link) fn restore_rs485(&self, _: &Saved) -> OsResult<()> {
            Err(not_here())
        }

        pub(in crate::link) fn set_low_latency(&self) -> OsResult<()> {
            Err(not_here())
        }

        pub(in crate::link) fn modem_lines(&self) -> OsResult<ModemLines> {
            Err(not_here())
        }

        pub(in crate::link) fn set_rs485(&self, _: &Rs485) -> OsResult<()> {
            Err(not_here())
        }

        pub(in crate::link) fn counters(&self) -> OsResult<Counters> {
            Err(not_here())
        }

        pub(in crate::link) fn keep_lines_on_close(&self) -> OsResult<()> {
            Err(not_here())
        }

        pub(in crate::link) fn drain(&self) -> OsResult<()> {
            Err(not_here())
        }
    }
}
