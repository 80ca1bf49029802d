#!/usr/bin/env python3
"""The JSON Schemas of docs/schema/ against the examples and against the readers.

Usage: check_schemas.py SOURCE_DIR BPDE_BINARY

1. Every JSON file under examples/ validates against its schema (blend configs against
   blend.schema.json, jobs against job.schema.json).
2. On a few mutations of an example job, blend config and net (unknown field, wrong type, missing
   field, value out of range), the schema rejects exactly when the reader (the bpde binary)
   rejects with exit 2; the unmutated files pass both.
Exit 0 when all hold; the failures are printed.
"""
import copy
import json
import math
import os
import pathlib
import subprocess
import sys
import tempfile

import jsonschema

SOURCE = pathlib.Path(sys.argv[1])
BPDE = sys.argv[2]
SCHEMAS = SOURCE / "docs" / "schema"
failures = []


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def validator(name):
    """A validator of docs/schema/NAME, its relative $refs resolved among the schema files."""
    schemas = {p.name: load(p) for p in SCHEMAS.glob("*.schema.json")}
    cls = jsonschema.validators.validator_for(schemas[name])
    cls.check_schema(schemas[name])
    try:  # jsonschema >= 4.18
        from referencing import Registry, Resource

        registry = Registry().with_resources((n, Resource.from_contents(s)) for n, s in schemas.items())
        return cls(schemas[name], registry=registry)
    except ImportError:  # Debian 12: jsonschema 4.10
        resolver = jsonschema.RefResolver(base_uri=name, referrer=schemas[name], store=schemas)
        return cls(schemas[name], resolver=resolver)


JOB, BLEND, NET = validator("job.schema.json"), validator("blend.schema.json"), validator("net.schema.json")
SWEEP = validator("sweep.schema.json")


def schema_errors(v, doc):
    return [f"{'/'.join(map(str, e.absolute_path)) or '(root)'}: {e.message[:160]}" for e in v.iter_errors(doc)]


# 1. Every example validates.
examples = sorted((SOURCE / "examples").rglob("*.json"))
if not examples:
    failures.append("no example JSON found under examples/")
for path in examples:
    doc = load(path)
    v = BLEND if doc.get("kind") == "blend" else SWEEP if "axes" in doc else JOB
    for e in schema_errors(v, doc):
        failures.append(f"{path.relative_to(SOURCE)}: {e}")

# 2. The schemas reject what the readers reject.
tmp = pathlib.Path(tempfile.mkdtemp(prefix="bpde_schema_"))


def reader_exit(command, doc):
    """Exit status of `bpde COMMAND FILE [...]` on doc (2: the reader refused it)."""
    f = tmp / "input.json"
    f.write_text(json.dumps(doc), encoding="utf-8")
    out = tmp / "out"
    args = {"solve": ["solve", str(f), "--out", str(out), "--quiet", "--samples", "2"],
            "blend": ["blend", str(f), "--out", str(out)],
            "check": ["check", str(f), "--samples", "2"]}[command]
    return subprocess.run([BPDE] + args, capture_output=True, timeout=300).returncode


def mutate(doc, path, value=None, delete=False):
    d = copy.deepcopy(doc)
    node = d
    for k in path[:-1]:
        node = node[k]
    if delete:
        del node[path[-1]]
    else:
        node[path[-1]] = value
    return d


job = load(SOURCE / "examples" / "001-pde-figures" / "fig1-biharmonic.json")
cmc = load(SOURCE / "examples" / "004-cmc-circle" / "n4-b-H-1.json")
blend = load(SOURCE / "examples" / "003-blend-cylinders" / "fig2a.json")
curves = load(SOURCE / "examples" / "004-cmc-circle" / "circle_curves.json")
builder = mutate(load(SOURCE / "examples" / "004-cmc-circle" / "circle_builder.json"), ["boundary", "degree"], 4)
net = {"type": "triangular", "degree": 1, "points": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}
# circle_curves.json's edge 2 (the unit circle's arc from 2π/3 to 4π/3) as 21 samples without
# parameters; the end points as the arcs compute them (cos, sin of the angles).
_a = curves["boundary"]["edges"][2]["angles"]
samples = {"type": "samples", "points": [[math.cos(a), math.sin(a), 0.0]
                                         for a in (_a[0] + (_a[1] - _a[0]) * k / 20 for k in range(21))]}

cases = [
    # (what, command, validator, document, the reader and the schema accept it)
    ("job as it is", "solve", JOB, job, True),
    ("job without samples and fixed", "solve", JOB, mutate(mutate(job, ["samples"], delete=True), ["fixed"],
                                                              delete=True), True),
    ("job: unknown top-level field", "solve", JOB, mutate(job, ["sample"], 50), False),
    ("job: unknown problem field", "solve", JOB, mutate(job, ["problem", "methd"], "lu"), False),
    ("job: samples of the wrong type", "solve", JOB, mutate(job, ["samples"], "50"), False),
    ("job: samples out of range", "solve", JOB, mutate(job, ["samples"], 2001), False),
    ("job: missing problem", "solve", JOB, mutate(job, ["problem"], delete=True), False),
    ("job: unknown method", "solve", JOB, mutate(job, ["problem", "method"], "qr"), False),
    ("job: unknown fixed set", "solve", JOB, mutate(job, ["fixed"], "all"), False),
    ("job: degree above 64", "solve", JOB, mutate(job, ["net", "degree"], [65, 5]), False),
    ("job: operator energy in an extremal", "solve", JOB,
     mutate(job, ["problem"], {"kind": "extremal", "energy": {"name": "operator", "coeffs": [1, 0, 2, 0, 1]}}), False),
    ("job: extremal energy missing its coeffs", "solve", JOB,
     mutate(job, ["problem"], {"kind": "extremal", "energy": {"name": "fourth-order"}}), False),
    ("cmc job as it is", "solve", JOB, cmc, True),
    ("cmc job with both H and V", "solve", JOB, mutate(cmc, ["problem", "V"], 1.0), False),
    ("cmc job with V and solver newton", "solve", JOB, mutate(mutate(cmc, ["problem", "H"], delete=True),
                                                            ["problem", "V"], 1.0), False),
    ("boundary-form job as it is", "solve", JOB, curves, True),
    ("job with both net and boundary", "solve", JOB, mutate(curves, ["net"], net), False),
    ("boundary: unknown curve type", "solve", JOB, mutate(curves, ["boundary", "edges", 2, "type"], "spline"), False),
    ("boundary: unknown builder", "solve", JOB, mutate(builder, ["boundary", "builder"], "circle"), False),
    ("boundary: samples without parameters", "solve", JOB, mutate(curves, ["boundary", "edges", 2], samples), True),
    ("boundary: samples at the chord length", "solve", JOB,
     mutate(curves, ["boundary", "edges", 2], dict(samples, parameters="chord-length")), True),
    ("boundary: unknown sample parameters", "solve", JOB,
     mutate(curves, ["boundary", "edges", 2], dict(samples, parameters="arc")), False),
    ("area cmc job as it is", "solve", JOB, mutate(builder, ["problem", "functional"], "area"), True),
    ("cmc job: unknown functional", "solve", JOB, mutate(builder, ["problem", "functional"], "areas"), False),
    ("area cmc job with solver nlopt", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "area"), ["problem", "solver"], "nlopt"), False),
    ("mean-curvature cmc job as it is", "solve", JOB, mutate(builder, ["problem", "functional"], "mean-curvature"),
     True),
    ("mean-curvature cmc job with its tolerance", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "mean-curvature"), ["problem", "mean_curvature_tolerance"], 1e-3),
     True),
    ("mean-curvature cmc job with solver ceres", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "mean-curvature"), ["problem", "solver"], "ceres"), True),
    ("mean-curvature cmc job with solver nlopt", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "mean-curvature"), ["problem", "solver"], "nlopt"), False),
    ("mean-curvature cmc job with V", "solve", JOB,
     mutate(mutate(mutate(builder, ["problem", "functional"], "mean-curvature"), ["problem", "H"], delete=True),
            ["problem", "V"], 1.0), True),
    ("mean-curvature cmc job with V and solver newton", "solve", JOB,
     mutate(mutate(mutate(mutate(builder, ["problem", "functional"], "mean-curvature"), ["problem", "H"], delete=True),
                   ["problem", "V"], 1.0), ["problem", "solver"], "newton"), True),
    ("mean-curvature cmc job with V and solver ceres", "solve", JOB,
     mutate(mutate(mutate(mutate(builder, ["problem", "functional"], "mean-curvature"), ["problem", "H"], delete=True),
                   ["problem", "V"], 1.0), ["problem", "solver"], "ceres"), True),
    ("mean-curvature cmc job with V and solver nlopt", "solve", JOB,
     mutate(mutate(mutate(mutate(builder, ["problem", "functional"], "mean-curvature"), ["problem", "H"], delete=True),
                   ["problem", "V"], 1.0), ["problem", "solver"], "nlopt"), False),
    ("area cmc job with V and solver ceres", "solve", JOB,
     mutate(mutate(mutate(mutate(builder, ["problem", "functional"], "area"), ["problem", "H"], delete=True),
                   ["problem", "V"], 1.0), ["problem", "solver"], "ceres"), True),
    ("area cmc job with V and solver nlopt", "solve", JOB,
     mutate(mutate(mutate(mutate(builder, ["problem", "functional"], "area"), ["problem", "H"], delete=True),
                   ["problem", "V"], 1.0), ["problem", "solver"], "nlopt"), False),
    ("mean-curvature tolerance out of range", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "mean-curvature"), ["problem", "mean_curvature_tolerance"], 1.0),
     False),
    ("mean-curvature cmc job with an unknown solver", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "mean-curvature"), ["problem", "solver"], "foo"), False),
    ("area cmc job with start dirichlet", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "area"), ["problem", "start"], "dirichlet"), True),
    ("area cmc job with start minimal-surface", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "area"), ["problem", "start"], "minimal-surface"), True),
    ("area cmc job with an unknown start", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "area"), ["problem", "start"], "plane"), False),
    ("start with the mean-curvature functional", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "mean-curvature"), ["problem", "start"], "dirichlet"), False),
    ("mean_curvature_tolerance with the area functional", "solve", JOB,
     mutate(mutate(builder, ["problem", "functional"], "area"), ["problem", "mean_curvature_tolerance"], 1e-3), False),
    ("job: unknown mesh_format", "solve", JOB, mutate(job, ["mesh_format"], "float"), False),
    ("job: unknown export", "solve", JOB, mutate(job, ["export"], ["iges"]), False),
    ("blend config as it is", "blend", BLEND, blend, True),
    ("blend: unknown field", "blend", BLEND, mutate(blend, ["b"], 1), False),
    ("blend: missing epsilon", "blend", BLEND, mutate(blend, ["epsilon"], delete=True), False),
    ("blend: partition of the wrong type", "blend", BLEND, mutate(blend, ["partition"], "4x4"), False),
    ("blend: epsilon zero", "blend", BLEND, mutate(blend, ["epsilon"], 0), False),
    ("blend: edge without dy", "blend", BLEND, mutate(blend, ["edges", "y0", "dy"], delete=True), False),
    ("net as it is", "check", NET, net, True),
    ("net: unknown field", "check", NET, mutate(net, ["knots"], []), False),
    ("net: missing points", "check", NET, mutate(net, ["points"], delete=True), False),
    ("net: a point of two numbers", "check", NET, mutate(net, ["points", 2], [0, 1]), False),
    ("net: degree of the wrong type", "check", NET, mutate(net, ["degree"], [1, 1]), False),
    ("net: unknown type", "check", NET, mutate(net, ["type"], "quad"), False),
]
for what, command, v, doc, valid in cases:
    errors = schema_errors(v, doc)
    status = reader_exit(command, doc)
    if valid and (errors or status == 2):
        failures.append(f"{what}: should pass; schema says {errors[:2]}, bpde {command} exit {status}")
    if not valid and (not errors or status != 2):
        failures.append(f"{what}: should be refused; schema errors {len(errors)}, bpde {command} exit {status}")

for f in failures:
    print("FAIL", f)
print(f"{len(examples)} examples, {len(cases)} reader cases, {len(failures)} failures")
sys.exit(1 if failures else 0)
