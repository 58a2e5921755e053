"""A stage of the kit's emitted Verilog, driven by cocotb from the vectors
`cube stage-vectors` exports (the golden model's stimulus and expected
outputs): every output is checked on every clock once the pipeline is full.

The vectors file is named by the environment variable CUBE_STAGE_VECTORS.
Run it with run.py, which builds the Verilog under Icarus or Verilator.
"""

import json
import os

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import ReadOnly, RisingEdge, Timer


@cocotb.test()
async def stage_matches_the_golden_model(dut):
    with open(os.environ["CUBE_STAGE_VECTORS"]) as f:
        spec = json.load(f)
    clock = getattr(dut, spec["clock"])
    latency = spec["latency"]
    inputs, expected = spec["inputs"], spec["expected"]
    # Rising edges at 10t + 5, as the kit's own testbenches clock it.
    clock.value = 0
    cocotb.start_soon(Clock(clock, 10, unit="ns").start(start_high=False))
    checked = 0
    for t, vector in enumerate(inputs):
        for name, value in vector.items():
            getattr(dut, name).value = value
        await RisingEdge(clock)
        await ReadOnly()
        i = t + 1 - latency
        if i >= 0:
            for name, want in expected[i].items():
                got = getattr(dut, name).value
                assert got.is_resolvable, f"clock {t}: {name} is {got}"
                assert int(got) == want, (
                    f"clock {t}: {name} = {int(got)}, golden model {want} "
                    f"(inputs of clock {i}: {inputs[i]})"
                )
                checked += 1
        await Timer(1, unit="ns")
    dut._log.info("%d outputs checked over %d clocks", checked, len(inputs))
    assert checked == (len(inputs) + 1 - latency) * len(expected[0])
