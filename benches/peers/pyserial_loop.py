"""The loop a user writes today without tmclsh: pyserial, the module's ASCII interface, GAP 1, 0
N times, each reply read and checked. The peer of the benchmark's host-overhead row.

Usage: python3 pyserial_loop.py PORT N [--read-until]

Puts module 1 into ASCII mode (binary command 139, as tmclsh does), reads the echo setting
(GGP 67, 0), then times N transactions: write the line, read the echo (if any) and the reply,
parse status and value. Prints the loop's elapsed seconds and the process's CPU seconds in the
loop on one line, then returns the module to binary mode.

Lines are read with whatever has arrived (`in_waiting`), the quickest a pyserial loop gets; with
`--read-until`, with `read_until(b"\r")` as pyserial's documentation shows and most scripts do
(pyserial then reads one byte per call).
"""

import sys
import time

import serial


class Line:
    """CR-terminated lines from a serial port, read with whatever has arrived."""

    def __init__(self, port):
        self.port = port
        self.buf = b""

    def read_line(self):
        while True:
            end = self.buf.find(b"\r")
            if end >= 0:
                line, self.buf = self.buf[:end], self.buf[end + 1 :]
                if line:
                    return line
                continue
            chunk = self.port.read(max(1, self.port.in_waiting))
            if not chunk:
                raise TimeoutError("no reply")
            self.buf += chunk


class ReadUntil:
    """CR-terminated lines from a serial port, read with pyserial's read_until."""

    def __init__(self, port):
        self.port = port

    def read_line(self):
        while True:
            line = self.port.read_until(b"\r")
            if not line.endswith(b"\r"):
                raise TimeoutError("no reply")
            if line != b"\r":
                return line[:-1]


def request(lines, port, text, echo):
    port.write(text + b"\r")
    if echo:
        seen = lines.read_line()
        if seen != text:
            raise AssertionError(f"echo {seen!r} for {text!r}")
    host_module, status, value = lines.read_line().split()
    if host_module != b"BA" or status != b"100":
        raise AssertionError(f"reply {host_module!r} {status!r}")
    return int(value)


def main(path, n, read_until):
    port = serial.Serial(path, 115200, timeout=1)
    frame = bytes([1, 139, 0, 0, 0, 0, 0, 0])
    port.write(frame + bytes([sum(frame) & 0xFF]))
    reply = port.read(9)
    if len(reply) != 9 or reply[2] != 100:
        raise AssertionError(f"no reply to 139: {reply!r}")
    port.write(b"\r")
    lines = ReadUntil(port) if read_until else Line(port)
    # The echo mode is not known yet: send without expecting an echo, and take the reply line.
    port.write(b"AGGP 67, 0\r")
    while True:
        line = lines.read_line()
        if line.startswith(b"BA "):
            break
    echo = (int(line.split()[2]) >> 4) & 3 < 2
    request(lines, port, b"AGAP 1, 0", echo)
    start, cpu = time.perf_counter(), time.process_time()
    for _ in range(n):
        request(lines, port, b"AGAP 1, 0", echo)
    elapsed, cpu = time.perf_counter() - start, time.process_time() - cpu
    # Back to binary mode, as tmclsh leaves the module: the echo (if any), then the reply.
    port.write(b"ABIN\r")
    for _ in range(2 if echo else 1):
        lines.read_line()
    print(f"{elapsed:.9f} {cpu:.9f}", flush=True)


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]), "--read-until" in sys.argv[3:])
