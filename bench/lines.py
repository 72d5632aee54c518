"""How the benchmark scripts run a normzoo benchmark program: one JSON object per output line."""
import json
import subprocess


def run_lines(cmd):
    """The program's output, each line a JSON object, parsed; raises if it exits non-zero."""
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return [json.loads(line) for line in out.splitlines()]
