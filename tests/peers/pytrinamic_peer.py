"""A third-party client against the simulator: PyTrinamic's own serial TMCL interface, unchanged.

Usage: python3 pytrinamic_peer.py PTY_PATH

Reads and writes axis parameters, moves the motor and prints one line per step ("ok STEP ...");
any mismatch raises, so the exit status tells the test what happened.
"""

import sys
import time

from pytrinamic.connections import ConnectionManager


def check(step, got, expected):
    if got != expected:
        raise AssertionError(f"{step}: expected {expected!r}, got {got!r}")
    print(f"ok {step} {got!r}", flush=True)


def main(port):
    manager = ConnectionManager(["--interface", "serial_tmcl", "--port", port, "--data-rate", "9600"])
    with manager.connect() as module:
        check("version", module.get_version_string(), "142V1.06")
        check("get_axis_parameter 4 default", module.get_axis_parameter(4, 0), 1000000)
        module.set_axis_parameter(255, 0, 1)  # velocities in pps
        module.set_axis_parameter(4, 0, 20000)
        module.set_axis_parameter(5, 0, 200000)
        check("set_axis_parameter 4", module.get_axis_parameter(4, 0), 20000)
        module.store_axis_parameter(4, 0)
        check("global 76 host address", module.get_global_parameter(76, 0), 2)
        module.set_global_parameter(10, 2, -5)
        check("user variable", module.get_global_parameter(10, 2, signed=True), -5)
        check("move_to", module.move_to(0, 5000), 5000)
        deadline = time.monotonic() + 20
        while not module.get_axis_parameter(8, 0):
            if time.monotonic() > deadline:
                raise AssertionError("the move never finished")
        check("position after move_to", module.get_axis_parameter(1, 0, signed=True), 5000)
        check("move_by target", module.move_by(0, -7000) & 0xFFFFFFFF, (-2000) & 0xFFFFFFFF)
        deadline = time.monotonic() + 20
        while module.get_axis_parameter(1, 0, signed=True) != -2000:
            if time.monotonic() > deadline:
                raise AssertionError("move_by never arrived")
        check("position after move_by", module.get_axis_parameter(1, 0, signed=True), -2000)
        module.rotate(0, 1000)
        deadline = time.monotonic() + 20
        while module.get_axis_parameter(3, 0, signed=True) != 1000:
            if time.monotonic() > deadline:
                raise AssertionError("rotate never reached its speed")
        check("rotate speed", module.get_axis_parameter(3, 0, signed=True), 1000)
        module.stop(0)
        check("target speed after stop", module.get_axis_parameter(2, 0, signed=True), 0)
        module.set_digital_output(1)
        check("digital output", module.get_digital_output(1), 1)
        check("digital input", module.get_digital_input(3), 0)
        check("reference search status", module.reference_search(2, 0), 0)


if __name__ == "__main__":
    main(sys.argv[1])
