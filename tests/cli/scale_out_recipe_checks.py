"""What docs/scale-out.md's recipes must keep to survive a real cluster, checked on the parsed
manifests (PyYAML) and the shell text. Each check returns the problems it found, as sentences
naming the manifest or script, so that removing a point from the doc fails the test saying which.
"""
import re

RENDER_PINNED = re.compile(r"hexray render\b(?=.*--backend (?:gpu --device \S+|cpu)\b)")
RUN_PLACEHOLDER = "${RUN}"


def container(job):
    return job["spec"]["template"]["spec"]["containers"][0]


def name(document):
    return f"{document['kind']} {document['metadata']['name']}"


def check_render_pinned(what, command):
    command = command.replace("\\\n", " ")
    if "hexray render" not in command:
        return [f"{what}: no hexray render"]
    if "--backend auto" in command or not RENDER_PINNED.search(command):
        return [f"{what}: the renderer is not pinned (--backend gpu --device D, or --backend cpu)"]
    return []


def check_resources(job):
    resources = container(job).get("resources") or {}
    missing = [f"{kind}.{what}" for kind in ("requests", "limits") for what in ("cpu", "memory")
               if what not in (resources.get(kind) or {})]
    return [f"{name(job)}: no resources {', '.join(missing)}"] if missing else []


def check_threads_follow_cpu_limit(job, command):
    strip = container(job)
    env = {e["name"]: e for e in strip.get("env", [])}
    field = env.get("LP_NUM_THREADS", {}).get("valueFrom", {}).get("resourceFieldRef", {})
    problems = []
    if field.get("resource") != "limits.cpu" or field.get("containerName", strip["name"]) != strip["name"]:
        problems.append(f"{name(job)}: LP_NUM_THREADS does not come from its limits.cpu (resourceFieldRef)")
    if '--threads "$LP_NUM_THREADS"' not in command:
        problems.append(f'{name(job)}: hexray render is not given --threads "$LP_NUM_THREADS"')
    return problems


def check_shared_volume(documents, workloads):
    claims = {d["metadata"]["name"]: d for d in documents if d.get("kind") == "PersistentVolumeClaim"}
    problems = [f"PersistentVolumeClaim {c}: not ReadWriteMany" for c, d in claims.items()
                if "ReadWriteMany" not in d["spec"].get("accessModes", [])]
    if not claims:
        problems.append("no PersistentVolumeClaim defined")
    for workload in workloads:
        spec = workload["spec"]["template"]["spec"] if workload["kind"] == "Job" else workload["spec"]
        volumes = {v["name"] for v in spec.get("volumes", [])
                   if v.get("persistentVolumeClaim", {}).get("claimName") in claims}
        mounts = [m for m in spec["containers"][0].get("volumeMounts", []) if m["name"] in volumes]
        if not mounts:
            problems.append(f"{name(workload)}: does not mount the ReadWriteMany claim")
    return problems


def check_per_run(job):
    problems = []
    if RUN_PLACEHOLDER not in job["metadata"]["name"]:
        problems.append(f"{name(job)}: its name has no {RUN_PLACEHOLDER} (two runs would share the Job)")
    if RUN_PLACEHOLDER not in container(job).get("workingDir", ""):
        problems.append(f"{name(job)}: its workingDir has no {RUN_PLACEHOLDER} (two runs would share pieces)")
    return problems


def check_retries_per_index(job):
    spec = job["spec"]
    problems = []
    if not isinstance(spec.get("backoffLimitPerIndex"), int):
        problems.append(f"{name(job)}: no backoffLimitPerIndex (per-strip retries)")
    if spec["template"]["spec"].get("restartPolicy") != "Never":
        problems.append(f"{name(job)}: restartPolicy is not Never")
    return problems


def check_kubernetes_driver(script):
    problems = []
    waits = set(re.findall(r"kubectl wait --for=condition=(\w+) job", script, re.I))
    outcome_loop = re.search(r"\.status\.conditions", script) and re.search(r'"\s*Failed\s*"', script)
    if not outcome_loop and not {"complete", "failed"} <= {w.lower() for w in waits}:
        problems.append("the Kubernetes run does not stop waiting when a Job is Failed")
    if {w.lower() for w in waits} == {"complete"}:
        problems.append("the Kubernetes run waits with --for=condition=complete alone")
    if not re.search(r"kubectl cp \S+ \S+:", script):
        problems.append("the Kubernetes run does not copy the scene in (kubectl cp)")
    if not re.search(r"kubectl cp \S+:\S+ ", script):
        problems.append("the Kubernetes run does not copy the frame out (kubectl cp)")
    if not re.search(r"sed [^|]*\$\{?run\b[^|]*\| kubectl apply", script):
        problems.append("the Kubernetes run does not put its run id into the manifests it applies")
    return problems


def check_slurm_strips(script):
    problems = check_render_pinned("strips.sbatch", script)
    for option in ("--cpus-per-task", "--mem"):
        if not re.search(rf"^#SBATCH {option}=\S+", script, re.M):
            problems.append(f"strips.sbatch: no #SBATCH {option}")
    if not re.search(r'^export LP_NUM_THREADS="\$SLURM_CPUS_PER_TASK"$', script, re.M):
        problems.append("strips.sbatch: LP_NUM_THREADS does not come from SLURM_CPUS_PER_TASK")
    if '--threads "$SLURM_CPUS_PER_TASK"' not in script:
        problems.append('strips.sbatch: hexray render is not given --threads "$SLURM_CPUS_PER_TASK"')
    return problems


def check_slurm_submission(script):
    problems = []
    if "afterok" in script or not re.search(r"sbatch .*--dependency=afterany:\S+.* merge\.sbatch", script):
        problems.append("the Slurm merge does not run after any end of the strips (--dependency=afterany)")
    for job in ("strips", "merge"):
        if not re.search(rf'sbatch .*--chdir="runs/\$run".* {job}\.sbatch', script):
            problems.append(f'the Slurm {job} job does not run in the run\'s directory (--chdir="runs/$run")')
    if not re.search(r'cp \S+ "runs/\$run/scene\.json"', script):
        problems.append("the Slurm run does not copy the scene into its directory")
    return problems
