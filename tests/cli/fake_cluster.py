#!/usr/bin/python3
"""A stand-in for kubectl and sbatch, enough to run docs/scale-out.md's run scripts on one machine.

Called as `kubectl` or `sbatch` (links by those names on the PATH). Every ReadWriteMany claim is
the directory $FAKE_CLUSTER_VOLUME; pods and tasks run at once, as local processes, in order; a
Job's or array's state is kept in $FAKE_CLUSTER_STATE. The task or pod of index
$FAKE_CLUSTER_FAIL_INDEX (if set) fails every attempt without running, as on a node that is lost.

kubectl: apply -f FILE|-, wait --for=condition=Ready pod/NAME, exec POD -- ARGS, cp SRC DST (one
side POD:PATH), get job/NAME -o jsonpath=... (the True conditions' types, as Kubernetes >= 1.31
sets them), logs job/NAME. sbatch: [--parsable] [--wait] [--chdir=DIR] [--dependency=afterok:ID |
afterany:ID] SCRIPT; a merge that afterok would leave pending for ever exits 99 saying so.
"""
import json
import os
import re
import subprocess
import sys

import yaml

sys.dont_write_bytecode = True  # nothing written into the source tree
from scale_out_commands import environment  # noqa: E402

VOLUME = os.environ.get("FAKE_CLUSTER_VOLUME", "")
STATE = os.environ.get("FAKE_CLUSTER_STATE", "")
FAILING = os.environ.get("FAKE_CLUSTER_FAIL_INDEX", "")
CONDITIONS_PATH = '{.status.conditions[?(@.status=="True")].type}'


def fail(message):
    sys.exit(f"fake {os.path.basename(sys.argv[0])}: {message}")


def state(name, value=None):
    path = os.path.join(STATE, re.sub(r"[^\w.-]", "_", name) + ".json")
    if value is not None:
        with open(path, "w", encoding="utf-8") as file:
            json.dump(value, file)
    elif os.path.exists(path):
        with open(path, encoding="utf-8") as file:
            return json.load(file)
    return value


def local_path(spec, path):
    """Where a pod's path lies here: under the mount of a persistentVolumeClaim volume."""
    claims = {v["name"] for v in spec.get("volumes", []) if "persistentVolumeClaim" in v}
    for mount in spec["containers"][0].get("volumeMounts", []):
        if mount["name"] in claims and os.path.commonpath([path, mount["mountPath"]]) == mount["mountPath"]:
            return os.path.join(VOLUME, os.path.relpath(path, mount["mountPath"]))
    fail(f"{path} is on no shared volume of the pod")


def run_pod(job, index):
    spec = job["spec"]["template"]["spec"]
    container = spec["containers"][0]
    if str(index) == FAILING:
        return 1, "lost with its node\n"
    variables = dict(os.environ)
    exports = "\n".join(environment(job))
    if index is not None:
        variables["JOB_COMPLETION_INDEX"] = str(index)
    result = subprocess.run(container["command"] + [exports + "\n" + container["args"][0]], text=True,
                            capture_output=True, env=variables, cwd=local_path(spec, container["workingDir"]))
    return result.returncode, result.stdout + result.stderr


def run_job(job):
    spec = job["spec"]
    indexes = range(spec["completions"]) if spec.get("completionMode") == "Indexed" else [None]
    attempts = 1 + spec.get("backoffLimitPerIndex", spec.get("backoffLimit", 6))
    logs, failed = [], False
    for index in indexes:
        for _ in range(attempts):
            code, output = run_pod(job, index)
            logs.append(output)
            if code == 0:
                break
        failed = failed or code != 0
    conditions = ["FailureTarget", "Failed"] if failed else ["SuccessCriteriaMet", "Complete"]
    state("job/" + job["metadata"]["name"], {"conditions": conditions, "log": logs[-1] if failed else logs[0]})


def apply(source):
    text = sys.stdin.read() if source == "-" else open(source, encoding="utf-8").read()
    for document in (d for d in yaml.safe_load_all(text) if d):
        if document["kind"] == "Pod":
            state("pod/" + document["metadata"]["name"], document)
        elif document["kind"] == "Job":
            run_job(document)
        print(f"{document['kind'].lower()}/{document['metadata']['name']} created")


def pod_side(argument):
    pod, path = argument.split(":", 1)
    return local_path(state("pod/" + pod)["spec"], path)


def kubectl(arguments):
    command = arguments[0]
    if command == "apply" and arguments[1] == "-f":
        apply(arguments[2])
    elif command == "wait" and arguments[1] == "--for=condition=Ready" and state(arguments[2]):
        print(f"{arguments[2]} condition met")
    elif command == "exec" and arguments[2] == "--":
        spec = state("pod/" + arguments[1])["spec"]
        words = [local_path(spec, w) if w.startswith("/") else w for w in arguments[3:]]
        sys.exit(subprocess.run(words).returncode)
    elif command == "cp":
        source, target = (pod_side(a) if ":" in a else a for a in arguments[1:3])
        sys.exit(subprocess.run(["cp", source, target]).returncode)
    elif command == "get" and arguments[2:] == ["-o", "jsonpath=" + CONDITIONS_PATH]:
        print(" ".join(state(arguments[1])["conditions"]), end="")
    elif command == "logs" and state(arguments[1]):
        print(state(arguments[1])["log"], end="")
    else:
        fail(f"not understood: kubectl {' '.join(arguments)}")


def sbatch(arguments):
    options = dict(re.fullmatch(r"--([\w-]+)(?:=(.*))?", a).groups() for a in arguments[:-1])
    script = open(arguments[-1], encoding="utf-8").read()
    options = {**dict(re.findall(r"^#SBATCH --([\w-]+)=(\S+)", script, re.M)), **options}
    identifier = str(len(os.listdir(STATE)) + 100)
    dependency = options.get("dependency")
    if dependency:
        kind, after = dependency.split(":")
        if kind == "afterok" and any(state("slurm/" + after)):
            fail(f"job {identifier} pending for ever: DependencyNeverSatisfied")
        if kind not in ("afterok", "afterany"):
            fail(f"dependency {dependency} not understood")
    indexes = [None]
    if "array" in options:
        first, last = map(int, options["array"].split("-"))
        indexes = range(first, last + 1)
    codes = [task(script, options, identifier, index) for index in indexes]
    state("slurm/" + identifier, codes)
    print(identifier + (";fake" if "parsable" in options else ""))
    sys.exit(max(codes) if "wait" in options else 0)


def task(script, options, identifier, index):
    directory = options.get("chdir", ".")
    log = options.get("output", "slurm-%j.out").replace("%a", str(index)).replace("%A", identifier)
    log = log.replace("%j", identifier)
    if str(index) == FAILING:
        return 1
    variables = {**os.environ, "SLURM_JOB_ID": identifier, "SLURM_CPUS_PER_TASK": options.get("cpus-per-task", "1")}
    if index is not None:
        variables["SLURM_ARRAY_TASK_ID"] = str(index)
    with open(os.path.join(directory, log), "w", encoding="utf-8") as output:
        return subprocess.run(["bash", "-c", script], stdout=output, stderr=subprocess.STDOUT, env=variables,
                              cwd=directory).returncode


if __name__ == "__main__":
    if not VOLUME or not STATE:
        fail("set FAKE_CLUSTER_VOLUME and FAKE_CLUSTER_STATE")
    {"kubectl": kubectl, "sbatch": sbatch}[os.path.basename(sys.argv[0])](sys.argv[1:])
