#!/usr/bin/env python3
"""equal_error.* (issue 40): runs docs/bench/equal-error-vs-vtk.sh on a 64^3 phantom, 2 steps,
one frame, and checks what it wrote, so that the benchmark cannot rot unnoticed:
- results.tsv has exactly the documented columns and one row per mode, renderer and step;
- PSNR against each renderer's own converged image (1/16 voxel) rises as the step shrinks
  from 2 to 1 voxel, for VTK and for Voxray, in dvr and in mip (halving the step halves the
  marching error of both; the phantom is smooth, so this holds by a margin of dB, not by
  chance), and so does Voxray's PSNR against the double-precision reference;
- every PSNR is finite and at most the 99 dB cap, every SSIM in (0, 1];
- the two renderers' silhouettes agree: the outlines of the converged images lie at most
  2 px apart (mean at most 1 px) at 160x120, where a camera off by one degree of orbit or
  5 % of view angle moves the phantom's outline by 2-3 px; the remaining pixel comes from the
  two reconstructions' edges (VTK's fixed-point scalars, Voxray's float);
- table.md carries the ratio lines and pareto.png is a PNG;
- the GPU machine's split (SCORE=off there: images and times only; SCORE=again here: scored)
  gives the same rows: a second run with SCORE=off writes NaN scores and no plot, and
  SCORE=again on its folder gives every row the PSNR and SSIM of the one-step run above
  (both renderers are deterministic on the CPU: equal images, so equal scores to the digit).

usage: equal_error_check.py SCRIPT CLI PYTHON DATA WORK
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

script, cli, python, data, work = sys.argv[1:6]
env = dict(os.environ, SCENES="phantom64", MODES="dvr,mip", STEPS="2,1", SIZE="160x120",
           ROUNDS="1", FRAMES="1", CLI=cli, PYTHON=python, DATA=data, DEVICE="cpu")
r = subprocess.run(["bash", script, work], env=env, capture_output=True, text=True)
if r.returncode != 0:
    sys.exit(f"equal-error-vs-vtk.sh failed ({r.returncode}):\n{r.stdout}\n{r.stderr}")

failures = []
with open(os.path.join(work, "results.tsv")) as f:
    reader = csv.DictReader(f, delimiter="\t")
    columns = ["scene", "mode", "renderer", "step_voxels", "ms_median", "psnr_own_db", "ssim_own",
               "psnr_ref_db", "ssim_ref"]
    if reader.fieldnames != columns:
        sys.exit(f"results.tsv columns {reader.fieldnames}, expected {columns}")
    rows = list(reader)
if len(rows) != 8:
    failures.append(f"{len(rows)} rows, expected 8 (2 modes x 2 renderers x 2 steps)")
by = {(r["mode"], r["renderer"], float(r["step_voxels"])): r for r in rows}
for mode in ("dvr", "mip"):
    for renderer in ("VTK fixed-point", "Voxray"):
        coarse, fine = by.get((mode, renderer, 2.0)), by.get((mode, renderer, 1.0))
        if not coarse or not fine:
            failures.append(f"{mode} {renderer}: rows for steps 2 and 1 missing")
            continue
        keys = ["psnr_own_db"] + (["psnr_ref_db"] if renderer == "Voxray" else [])
        for key in keys:
            a, b = float(coarse[key]), float(fine[key])
            print(f"{mode} {renderer} {key}: step 2 {a:.2f} dB, step 1 {b:.2f} dB")
            if not b > a:
                failures.append(f"{mode} {renderer}: {key} does not rise from step 2 ({a}) "
                                f"to step 1 ({b})")
for r in rows:
    for key in ("psnr_own_db", "psnr_ref_db"):
        if not (math.isfinite(float(r[key])) and float(r[key]) <= 99.0):
            failures.append(f"{r['mode']} {r['renderer']} {r['step_voxels']}: {key} {r[key]}")
    for key in ("ssim_own", "ssim_ref"):
        if not 0.0 < float(r[key]) <= 1.0:
            failures.append(f"{r['mode']} {r['renderer']} {r['step_voxels']}: {key} {r[key]}")
    if not float(r["ms_median"]) > 0.0:
        failures.append(f"{r['mode']} {r['renderer']}: time {r['ms_median']}")

table = open(os.path.join(work, "table.md")).read()
sil = re.findall(r"phantom64-(\w+): silhouettes .* outline distance mean ([0-9.]+) px, max "
                 r"([0-9.]+) px", table)
if len(sil) != 2:
    failures.append(f"table.md: {len(sil)} silhouette lines, expected 2")
for mode, mean, worst in sil:
    print(f"{mode} silhouettes: outline distance mean {mean} px, max {worst} px")
    if float(mean) > 1.0 or float(worst) > 2.0:
        failures.append(f"{mode}: the silhouettes lie apart (mean {mean}, max {worst} px)")
for mode in ("dvr", "mip"):
    if f"phantom64 {mode}: VTK's best error" not in table:
        failures.append(f"table.md: no ratio line for {mode}")
with open(os.path.join(work, "pareto.png"), "rb") as f:
    if f.read(8) != b"\x89PNG\r\n\x1a\n":
        failures.append("pareto.png is not a PNG")

split = work.rstrip("/") + "-split"
shutil.rmtree(split, ignore_errors=True)  # a plot left by an earlier run is not SCORE=off's
for score in ("off", "again"):
    r = subprocess.run(["bash", script, split], env=dict(env, SCORE=score), capture_output=True,
                       text=True)
    if r.returncode != 0:
        sys.exit(f"SCORE={score} failed ({r.returncode}):\n{r.stdout}\n{r.stderr}")
    with open(os.path.join(split, "results.tsv")) as f:
        split_rows = list(csv.DictReader(f, delimiter="\t"))
    if score == "off":
        bad = [r for r in split_rows if not math.isnan(float(r["psnr_own_db"]))]
        if len(split_rows) != 8 or bad:
            failures.append(f"SCORE=off: {len(split_rows)} rows, {len(bad)} with scores")
        if os.path.exists(os.path.join(split, "pareto.png")):
            failures.append("SCORE=off drew a plot")
split_by = {(r["mode"], r["renderer"], float(r["step_voxels"])): r for r in split_rows}
for key, r in by.items():
    s = split_by.get(key)
    if s is None:
        failures.append(f"SCORE=again: no row {key}")
        continue
    for col in ("psnr_own_db", "ssim_own", "psnr_ref_db", "ssim_ref"):
        if s[col] != r[col]:
            failures.append(f"SCORE=again {key} {col}: {s[col]}, one-step run {r[col]}")
    if not float(s["ms_median"]) > 0.0:
        failures.append(f"SCORE=again {key}: time {s['ms_median']}")
if not os.path.exists(os.path.join(split, "pareto.png")):
    failures.append("SCORE=again drew no plot")

if failures:
    sys.exit("\n".join(failures))
print("equal-error table checked: 8 rows, PSNR rises as the step shrinks for both renderers")
