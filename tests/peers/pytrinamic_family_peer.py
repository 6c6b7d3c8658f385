"""PyTrinamic's own module classes against the simulator: TMCM1140, TMCM6110 and TMCM6214,
unchanged, on one bus (the TMCM-1140 at address 1, the TMCM-6110 at address 2, the binary-only
TMCM-6214 at address 3).

Usage: python3 pytrinamic_family_peer.py PTY_PATH

Moves motors through the classes' move_to/rotate/stop (rotate with a negative speed on the
TMCM-6214, whose range is signed), reads positions and speeds back through
their motor objects, and sets per-axis parameters through their feature properties; prints one
line per step ("ok STEP ..."). Any mismatch raises, so the exit status tells the test what
happened.
"""

import sys
import time

from pytrinamic.connections import ConnectionManager
from pytrinamic.modules import TMCM1140, TMCM6110, TMCM6214


def check(step, got, expected):
    if got != expected:
        raise AssertionError(f"{step}: expected {expected!r}, got {got!r}")
    print(f"ok {step} {got!r}", flush=True)


def until(step, condition):
    deadline = time.monotonic() + 20
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError(f"{step}: never happened")


def tmcm1140(interface):
    module = TMCM1140(interface, module_id=1)
    motor = module.motors[0]
    check("1140 version", interface.get_version_string(module_id=1), "1140V127")
    motor.linear_ramp.max_velocity = 1500
    motor.linear_ramp.max_acceleration = 2000
    motor.drive_settings.max_current = 128
    check("1140 max_velocity", motor.linear_ramp.max_velocity, 1500)
    check("1140 max_current", motor.drive_settings.max_current, 128)
    module.move_to(0, 3000)
    until("1140 move_to", lambda: motor.get_position_reached())
    check("1140 position after move_to", motor.actual_position, 3000)
    module.move_by(0, -5000)
    until("1140 move_by", lambda: motor.get_position_reached())
    check("1140 position after move_by", motor.actual_position, -2000)
    module.set_digital_output(1)
    check("1140 digital output", module.get_digital_output(1), 1)
    check("1140 digital input", module.get_digital_input(3), 0)


def tmcm6110(interface):
    module = TMCM6110(interface, module_id=2)
    check("6110 version", interface.get_version_string(module_id=2), "6110V131")
    check("6110 motors", len(module.motors), 6)
    for axis, motor in enumerate(module.motors):
        motor.linear_ramp.max_velocity = 1000 + axis
        motor.drive_settings.standby_current = 10 + axis
    for axis, motor in enumerate(module.motors):
        check(f"6110 axis {axis} max_velocity", motor.linear_ramp.max_velocity, 1000 + axis)
        check(f"6110 axis {axis} standby_current", motor.drive_settings.standby_current, 10 + axis)
    module.move_to(3, 4000)
    motor3 = module.motors[3]
    until("6110 move_to axis 3", lambda: motor3.get_position_reached())
    check("6110 axis 3 position", motor3.actual_position, 4000)
    for axis in (0, 1, 2, 4, 5):
        check(f"6110 axis {axis} unmoved", module.motors[axis].actual_position, 0)
    module.rotate(1, 300)
    module.rotate(5, 400)
    until("6110 rotate axis 1", lambda: module.motors[1].actual_velocity == 300)
    until("6110 rotate axis 5", lambda: module.motors[5].actual_velocity == 400)
    module.stop(1)
    until("6110 stop axis 1", lambda: module.motors[1].actual_velocity == 0)
    check("6110 axis 5 still turning", module.motors[5].actual_velocity, 400)
    module.stop(5)
    module.set_digital_output(module.IO.OUT7)
    check("6110 digital output 7", module.get_digital_output(module.IO.OUT7), 1)
    check("6110 digital output 6", module.get_digital_output(module.IO.OUT6), 0)
    check("6110 analog input VIN", module.get_analog_input(module.IO.VIN), 0)


def tmcm6214(interface):
    module = TMCM6214(interface, module_id=3)
    check("6214 version", interface.get_version_string(module_id=3), "6214V117")
    for axis, motor in enumerate(module.motors):
        motor.linear_ramp.max_velocity = 100000 + axis
    check("6214 axis 5 max_velocity", module.motors[5].linear_ramp.max_velocity, 100005)
    check("6214 axis 0 max_velocity", module.motors[0].linear_ramp.max_velocity, 100000)
    module.move_to(5, -8000)
    until("6214 move_to axis 5", lambda: module.motors[5].get_axis_parameter(8))
    check("6214 axis 5 position", module.motors[5].actual_position, -8000)
    check("6214 axis 0 unmoved", module.motors[0].actual_position, 0)
    # A signed speed range (the manuals of its generation): rotate(axis, -v) turns left.
    module.rotate(2, -3000)
    motor2 = module.motors[2]
    until("6214 rotate axis 2 left", lambda: motor2.actual_velocity == -3000)
    check("6214 axis 2 turning left", motor2.actual_velocity, -3000)
    module.stop(2)
    until("6214 stop axis 2", lambda: motor2.actual_velocity == 0)
    if motor2.actual_position >= 0:
        raise AssertionError(f"6214 axis 2 ran right: {motor2.actual_position}")
    print(f"ok 6214 axis 2 ran left {motor2.actual_position < 0}", flush=True)


def main(port):
    manager = ConnectionManager(["--interface", "serial_tmcl", "--port", port, "--data-rate", "9600"])
    with manager.connect() as interface:
        tmcm1140(interface)
        tmcm6110(interface)
        tmcm6214(interface)


if __name__ == "__main__":
    main(sys.argv[1])
