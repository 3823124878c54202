#!/usr/bin/python3
"""Checks docs/scale-out.md and takes out the commands it gives each batch engine.

Usage: scale_out_commands.py DOC OUTDIR. Every ```yaml block must parse (PyYAML, Debian's
python3-yaml), every ```sh or ```bash block and every `sh -c` container command must pass
`bash -n`. Writes to OUTDIR the strip and merge commands of the Kubernetes Indexed Job and of the
Slurm array job (k8s-strip.sh, k8s-merge.sh, slurm-strip.sh, slurm-merge.sh) and each engine's
strip count (k8s-strips, slurm-strips), for the test to run them as local processes.
"""
import os
import re
import subprocess
import sys

import yaml


def blocks(text, languages):
    return [m.group(2) for m in re.finditer(r"^```(\w+)\n(.*?)^```", text, re.S | re.M) if m.group(1) in languages]


def check_shell(script, what):
    result = subprocess.run(["bash", "-n"], input=script, text=True, capture_output=True)
    if result.returncode != 0:
        sys.exit(f"{what}: bash -n: {result.stderr.strip()}")


def container_command(job):
    container = job["spec"]["template"]["spec"]["containers"][0]
    if container["command"] != ["sh", "-c"] or len(container["args"]) != 1:
        sys.exit(f"job {job['metadata']['name']}: expected command [sh, -c] and one argument")
    return container["args"][0]


def main(doc, out):
    text = open(doc, encoding="utf-8").read()
    jobs = []
    for index, block in enumerate(blocks(text, {"yaml"})):
        documents = [d for d in yaml.safe_load_all(block) if d is not None]
        if not documents:
            sys.exit(f"yaml block {index}: empty")
        jobs += [d for d in documents if d.get("kind") == "Job"]
    for index, block in enumerate(blocks(text, {"sh", "bash"})):
        check_shell(block, f"shell block {index}")
    for job in jobs:
        check_shell(container_command(job), f"job {job['metadata']['name']}")
    indexed = [j for j in jobs if j["spec"].get("completionMode") == "Indexed"]
    merges = [j for j in jobs if "hexray merge" in container_command(j)]
    scripts = blocks(text, {"bash"})
    arrays = [s for s in scripts if "#SBATCH --array=" in s]
    slurm_merges = [s for s in scripts if "#SBATCH" in s and "hexray merge" in s]
    if len(indexed) != 1 or len(merges) != 1 or len(arrays) != 1 or len(slurm_merges) != 1:
        sys.exit("expected one Indexed Job, one merge Job, one Slurm array script and one Slurm merge script")
    first, last = map(int, re.search(r"#SBATCH --array=(\d+)-(\d+)", arrays[0]).groups())
    if first != 0:
        sys.exit("the Slurm array must start at 0, as --strip numbers strips")
    files = {
        "k8s-strip.sh": container_command(indexed[0]),
        "k8s-merge.sh": container_command(merges[0]),
        "k8s-strips": str(indexed[0]["spec"]["completions"]),
        "slurm-strip.sh": arrays[0],
        "slurm-merge.sh": slurm_merges[0],
        "slurm-strips": str(last + 1),
    }
    for name, content in files.items():
        with open(os.path.join(out, name), "w", encoding="utf-8") as file:
            file.write(content + "\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
