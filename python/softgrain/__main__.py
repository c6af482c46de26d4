"""``python3 -m softgrain run SCENARIO.toml -o ROOT [--threads N] [--resume]``: one run, as
``softgrain run`` does it (the same run loop, the same files, bitwise), from Python alone.

It is what the children of ``softgrain.run_scenarios`` execute, so that a list of scenarios
built in Python runs through the campaign's process queue without the command line installed.
"""

import argparse
import os
import sys

import softgrain


def main(argv=None):
    """Parses the arguments and runs; returns the exit status (1 on a softgrain.Error)."""
    parser = argparse.ArgumentParser(prog="python3 -m softgrain")
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser("run", help="simulate a scenario, writing its run folder")
    run.add_argument("scenario", help="scenario TOML file")
    run.add_argument("-o", "--output", default=None, help="output root (default: the "
                     "scenario's [output] directory)")
    run.add_argument("--threads", type=int, default=0, help="OpenMP threads (0: all cores)")
    run.add_argument("--resume", action="store_true",
                     help="continue the run folder from its checkpoint.bin")
    args = parser.parse_args(argv)
    try:
        scenario = softgrain.Scenario.from_file(args.scenario)
        if args.resume:
            root = args.output or scenario.to_dict().get("output", {}).get("directory", "out")
            checkpoint = os.path.join(root, scenario.name, "checkpoint.bin")
            sim = softgrain.resume(checkpoint, scenario, threads=args.threads, output=root)
        else:
            sim = softgrain.Simulation(scenario, threads=args.threads,
                                       output=args.output or _output_root(scenario))
        sim.run()
        print(f"run '{scenario.name}': {sim.step_count} steps -> {sim.directory}")
        return 0
    except softgrain.Error as error:
        print(f"\nsoftgrain: error: {error}", file=sys.stderr)
        return 1


def _output_root(scenario):
    return scenario.to_dict().get("output", {}).get("directory", "out")


if __name__ == "__main__":
    sys.exit(main())
