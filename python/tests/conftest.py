"""Shared fixtures: the command-line binary and the source tree (set by ctest;
see python/CMakeLists.txt), for comparing the module with the command line."""

import json
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    binary = os.environ.get("ICPBENCH_BINARY")
    if not binary:
        pytest.skip("ICPBENCH_BINARY is not set (run through ctest)")

    def run(*args, check=True):
        done = subprocess.run([binary, *args], capture_output=True, text=True)
        if check and done.returncode != 0:
            raise AssertionError(f"icpbench {' '.join(args)}: exit {done.returncode}: {done.stderr}")
        return done

    run.json = lambda *args: json.loads(run(*args).stdout)
    return run


@pytest.fixture(scope="session")
def source_dir():
    return os.environ.get("ICPBENCH_SOURCE_DIR",
                          os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
