#!/usr/bin/python3
"""Checks docs/scale-out.md and takes out the commands it gives each batch engine.

Usage: scale_out_commands.py DOC OUTDIR RUN. Every ```yaml block must parse (PyYAML, Debian's
python3-yaml), every ```sh or ```bash block and every `sh -c` container command must pass
`bash -n`, and the recipes must keep what a real cluster needs (scale_out_recipe_checks.py).
Writes to OUTDIR, for run id RUN, the strip and merge commands of the Kubernetes Indexed Job and of
the Slurm array job (k8s-strip.sh, k8s-merge.sh, slurm-strip.sh, slurm-merge.sh), each preceded by
the environment its engine gives it (the container's env, its CPU limit resolved; Slurm's
SLURM_CPUS_PER_TASK), the run's directory relative to the shared volume, where they run
(k8s-rundir, slurm-rundir), and each engine's strip count (k8s-strips, slurm-strips), for the test
to run them as local processes; and the manifests, scripts and run scripts as the doc names them
(volume.yaml, strips.yaml, merge.yaml, strips.sbatch, merge.sbatch) and k8s-run.sh, slurm-run.sh,
for fake_cluster.py to run.
"""
import math
import os
import re
import shlex
import subprocess
import sys

import yaml

sys.dont_write_bytecode = True  # nothing written into the source tree
import scale_out_recipe_checks as checks  # noqa: E402


def blocks(text, languages):
    return [m.group(2) for m in re.finditer(r"^```(\w+)\n(.*?)^```", text, re.S | re.M) if m.group(1) in languages]


def check_shell(script, what):
    result = subprocess.run(["bash", "-n"], input=script, text=True, capture_output=True)
    if result.returncode != 0:
        sys.exit(f"{what}: bash -n: {result.stderr.strip()}")


def container_command(job):
    container = checks.container(job)
    if container["command"] != ["sh", "-c"] or len(container["args"]) != 1:
        sys.exit(f"job {job['metadata']['name']}: expected command [sh, -c] and one argument")
    return container["args"][0]


def only(items, what):
    if len(items) != 1:
        sys.exit(f"expected one {what}, found {len(items)}")
    return items[0]


def cpus(quantity):
    text = str(quantity)
    return float(text[:-1]) / 1000 if text.endswith("m") else float(text)


def environment(job):
    """The container's env as the kubelet would set it, a CPU resourceFieldRef rounded up as it does."""
    container = checks.container(job)
    lines = []
    for entry in container.get("env", []):
        if "value" in entry:
            value = entry["value"]
        else:
            field = entry["valueFrom"]["resourceFieldRef"]
            kind, resource = field["resource"].split(".")
            if resource != "cpu":
                sys.exit(f"{checks.name(job)}: env {entry['name']}: only CPU fields are resolved here")
            value = math.ceil(cpus(container["resources"][kind]["cpu"]) / cpus(field.get("divisor", 1)))
        lines.append(f"export {entry['name']}={shlex.quote(str(value))}")
    return lines


def run_directory(job, run):
    """The job's working directory, relative to the mount of the shared volume it lies on."""
    container = checks.container(job)
    working = container["workingDir"].replace(checks.RUN_PLACEHOLDER, run)
    for mount in container.get("volumeMounts", []):
        if os.path.commonpath([working, mount["mountPath"]]) == mount["mountPath"]:
            return os.path.relpath(working, mount["mountPath"])
    sys.exit(f"{checks.name(job)}: workingDir {working} is on no volume")


def manifest_name(documents):
    """The file the run script applies a manifest block as."""
    kinds = {d.get("kind") for d in documents}
    if "PersistentVolumeClaim" in kinds:
        return "volume.yaml"
    if any(d.get("kind") == "Job" and d["spec"].get("completionMode") == "Indexed" for d in documents):
        return "strips.yaml"
    return "merge.yaml" if kinds == {"Job"} else "other.yaml"


def kubernetes(text, run):
    documents, manifests = [], {}
    for index, block in enumerate(blocks(text, {"yaml"})):
        parsed = [d for d in yaml.safe_load_all(block) if d is not None]
        if not parsed:
            sys.exit(f"yaml block {index}: empty")
        documents += parsed
        manifests[manifest_name(parsed)] = block
    jobs = [d for d in documents if d.get("kind") == "Job"]
    for job in jobs:
        check_shell(container_command(job), f"job {job['metadata']['name']}")
    strips = only([j for j in jobs if j["spec"].get("completionMode") == "Indexed"], "Indexed Job")
    merge = only([j for j in jobs if "hexray merge" in container_command(j)], "merge Job")
    driver = only([b for b in blocks(text, {"sh", "bash"}) if "kubectl apply" in b], "Kubernetes run script")
    strip_command = container_command(strips)
    problems = checks.check_render_pinned(checks.name(strips), strip_command)
    problems += checks.check_resources(strips) + checks.check_resources(merge)
    problems += checks.check_threads_follow_cpu_limit(strips, strip_command)
    problems += checks.check_shared_volume(documents, jobs + [d for d in documents if d.get("kind") == "Pod"])
    problems += checks.check_per_run(strips) + checks.check_per_run(merge)
    problems += checks.check_retries_per_index(strips)
    problems += checks.check_kubernetes_driver(driver)
    if problems:
        return problems, {}
    files = {
        **manifests,
        "k8s-run.sh": driver,
        "k8s-strip.sh": "\n".join(environment(strips) + [strip_command]),
        "k8s-merge.sh": "\n".join(environment(merge) + [container_command(merge)]),
        "k8s-rundir": run_directory(strips, run),
        "k8s-strips": str(strips["spec"]["completions"]),
    }
    if run_directory(merge, run) != files["k8s-rundir"]:
        problems.append("the strips and the merge Job work in different directories")
    return problems, files


def slurm(text, run):
    scripts = blocks(text, {"bash"})
    strips = only([s for s in scripts if "#SBATCH --array=" in s], "Slurm array script")
    merge = only([s for s in scripts if "#SBATCH" in s and "hexray merge" in s], "Slurm merge script")
    submission = only([b for b in blocks(text, {"sh", "bash"}) if "sbatch " in b], "Slurm submission")
    problems = checks.check_slurm_strips(strips) + checks.check_slurm_submission(submission)
    first, last = map(int, re.search(r"#SBATCH --array=(\d+)-(\d+)", strips).groups())
    if first != 0:
        problems.append("the Slurm array must start at 0, as --strip numbers strips")
    cpus_per_task = re.search(r"^#SBATCH --cpus-per-task=(\d+)", strips, re.M)
    directory = re.search(r'--chdir="([^"]+)"', submission)
    files = {
        "strips.sbatch": strips,
        "merge.sbatch": merge,
        "slurm-run.sh": submission,
        "slurm-strip.sh": f"export SLURM_CPUS_PER_TASK={cpus_per_task.group(1) if cpus_per_task else 1}\n{strips}",
        "slurm-merge.sh": merge,
        "slurm-rundir": directory.group(1).replace("$run", run) if directory else ".",
        "slurm-strips": str(last + 1),
    }
    return problems, files


def main(doc, out, run):
    text = open(doc, encoding="utf-8").read()
    for index, block in enumerate(blocks(text, {"sh", "bash"})):
        check_shell(block, f"shell block {index}")
    k8s_problems, k8s_files = kubernetes(text, run)
    slurm_problems, slurm_files = slurm(text, run)
    if k8s_problems + slurm_problems:
        sys.exit("\n".join(f"{doc}: {problem}" for problem in k8s_problems + slurm_problems))
    for name, content in {**k8s_files, **slurm_files}.items():
        with open(os.path.join(out, name), "w", encoding="utf-8") as file:
            file.write(content + "\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3])
