"""A third-party client against the simulated bus served as an slcan adapter: PyTrinamic's own
SlcanTmclInterface (python-can's slcan bus underneath), unchanged.

Usage: python3 pytrinamic_slcan_peer.py PTY_PATH [MODULE_ID]

Sets and gets parameters, moves the motor and waits for position reached, printing one line per
step ("ok STEP ..."); any mismatch raises, so the exit status tells the test what happened.
"""

import sys
import time

from pytrinamic.connections import ConnectionManager


def check(step, got, expected):
    if got != expected:
        raise AssertionError(f"{step}: expected {expected!r}, got {got!r}")
    print(f"ok {step} {got!r}", flush=True)


def main(port, module_id):
    manager = ConnectionManager(
        ["--interface", "slcan_tmcl", "--port", port, "--data-rate", "1000000",
         "--module-id", module_id, "--host-id", "2"]
    )
    with manager.connect() as module:
        check("version", module.get_version_string(), "142V1.06")
        check("get_axis_parameter 4 default", module.get_axis_parameter(4, 0), 1000000)
        module.set_axis_parameter(255, 0, 1)  # velocities in pps
        module.set_axis_parameter(4, 0, 20000)
        module.set_axis_parameter(5, 0, 200000)
        check("set_axis_parameter 4", module.get_axis_parameter(4, 0), 20000)
        module.set_global_parameter(10, 2, -5)
        check("user variable", module.get_global_parameter(10, 2, signed=True), -5)
        check("move_to", module.move_to(0, 3000), 3000)
        deadline = time.monotonic() + 20
        while not module.get_axis_parameter(8, 0):
            if time.monotonic() > deadline:
                raise AssertionError("the move never finished")
        check("position reached", module.get_axis_parameter(8, 0), 1)
        check("position after move_to", module.get_axis_parameter(1, 0, signed=True), 3000)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "1")
