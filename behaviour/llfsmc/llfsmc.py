#!/usr/bin/env python3
"""llfsmc: compiles one LLFSM model (a .machine file) to C++ and a Graphviz diagram.
The compiler is the package next to this file (llfsmc/); see llfsmc/cli.py for the usage and
behaviour/README.md for the model format. Standard library only: it runs on the build host."""

import os
import sys

sys.dont_write_bytecode = True  # never leave __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from llfsmc.cli import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
