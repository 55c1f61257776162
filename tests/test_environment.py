"""etc/bashrc's environment takes effect in the processes it starts."""

import subprocess
import sys

HEAP_AFTER_A_LARGE_BLOCK = """
def heap_mb():
    for line in open("/proc/self/maps"):
        if line.rstrip().endswith("[heap]"):
            low, high = (int(x, 16) for x in line.split()[0].split("-"))
            return (high - low) >> 20
    return 0

block = bytearray(64 << 20)
held = heap_mb()
del block
print(held, heap_mb())
"""


def test_large_blocks_stay_on_the_heap(foam_env):
    """A block of 64 MB, beyond glibc's largest mmap threshold (32 MB, a
    tensor field of 0.47 M cells), comes from the heap and stays there
    once freed: glibc reads etc/bashrc's GLIBC_TUNABLES (a misspelt
    tunable is ignored silently). By default the block is a fresh mapping
    and the heap stays at a few MB, which cost large meshes a third of
    their time in the kernel (validation/benchmark_allocation.py)."""
    held, after_free = map(int, subprocess.run(
        [sys.executable, "-c", HEAP_AFTER_A_LARGE_BLOCK], env=foam_env,
        capture_output=True, text=True, check=True).stdout.split())
    assert held >= 64
    assert after_free >= 64


def dynamic_loader():
    """The path of glibc's dynamic loader, as this process mapped it."""
    for line in open("/proc/self/maps"):
        path = line.split()[-1]
        if "/ld-linux" in path:
            return path
    raise AssertionError("no glibc dynamic loader mapped in this process")


def test_the_heap_top_is_never_given_back(foam_env):
    """glibc gives the heap's free top back to the kernel once it exceeds
    the trim threshold; at 4.8 M cells per rank a step frees more than 1 GB
    there, and with a threshold of 1 GB the random bed at N = 48 spent
    28 % of its time in the kernel zeroing it again
    (validation/cases/allocation.md).
    The loader lists the tunables as this environment sets them."""
    listed = subprocess.run([dynamic_loader(), "--list-tunables"], env=foam_env,
                            capture_output=True, text=True, check=True).stdout
    values = dict(line.split(":")[:2] for line in listed.splitlines())
    assert values["glibc.malloc.mmap_max"].split()[0] == "0"
    assert int(values["glibc.malloc.trim_threshold"].split()[0], 16) == 2**64 - 1
