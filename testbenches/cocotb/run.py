"""Build a stage's emitted Verilog and run test_stage.py on it with cocotb.

    python run.py DIR [icarus|verilator]

DIR holds the files `cube stage-vectors --out DIR` writes: STAGE.v and
STAGE.json. Exits 0 when every output matched, 1 otherwise.
"""

import os
import sys
from pathlib import Path

from cocotb_tools.runner import get_results, get_runner


def main() -> int:
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    folder = Path(sys.argv[1]).resolve()
    simulator = sys.argv[2] if len(sys.argv) == 3 else "icarus"
    (verilog,) = folder.glob("*.v")
    vectors = verilog.with_suffix(".json")
    build = folder / f"build_{simulator}"
    runner = get_runner(simulator)
    runner.build(
        sources=[verilog],
        hdl_toplevel="top",
        build_dir=build,
        timescale=("1ns", "1ps"),
        # rust-hdl's Verilog widens and truncates on purpose (the kit's
        # own lint waives those rules): Verilator warns, but goes on.
        build_args=["-Wno-fatal", "-Wno-WIDTH"] if simulator == "verilator" else [],
        always=True,
    )
    results = runner.test(
        hdl_toplevel="top",
        test_module="test_stage",
        # Runs (and results.xml) in the build folder: never in the sources,
        # and two runs on two folders never share one. test_stage.py is found
        # on this script's path.
        test_dir=build,
        build_dir=build,
        extra_env={"CUBE_STAGE_VECTORS": str(vectors)},
        timescale=("1ns", "1ps"),
    )
    tests, failed = get_results(results)
    print(f"cocotb: {tests - failed} of {tests} tests passed")
    return 0 if tests > 0 and failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
