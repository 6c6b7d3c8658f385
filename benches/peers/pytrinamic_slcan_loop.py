"""PyTrinamic's CAN loop over slcan: SlcanTmclInterface (python-can's slcan bus), GAP 1, 0 N
times, each reply read and checked. The peer of the benchmark's slcan row.

Usage: python3 pytrinamic_slcan_loop.py PTY N

Prints the loop's elapsed seconds and the number of replies taken (which must be N).
"""

import sys
import time

from pytrinamic.connections import ConnectionManager


def main(port, n):
    manager = ConnectionManager(
        ["--interface", "slcan_tmcl", "--port", port, "--data-rate", "1000000"]
    )
    with manager.connect() as module:
        replies = 0
        start = time.perf_counter()
        for _ in range(n):
            module.get_axis_parameter(1, 0)
            replies += 1
        elapsed = time.perf_counter() - start
    print(f"{elapsed:.6f} {replies}")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]))
