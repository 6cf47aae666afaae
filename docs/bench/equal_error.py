#!/usr/bin/env python3
"""Speed at equal error, Voxray against VTK (issue 40): docs/bench/equal-error-vs-vtk.sh runs it.

For each scene and mode (dvr, mip) both renderers draw the same view of the same voxels with
the same transfer function and shading at each step (in voxels of the smallest spacing), and
once at 1/16 voxel (each renderer's own converged image). Voxray's double-precision host
renderer (voxray-cli render --reference) at 1/16 voxel is the common reference. Every image
is scored (PSNR, SSIM) against its own converged image and against that reference; times are
medians of FRAMES frames per round, VTK and Voxray taking turns round by round.

The same camera: Voxray's orbit camera (engine/src/camera.cpp, makeViewGeometry) turned into
VTK's: world = patient LPS mm with the origin at the volume's centre (VTK's image origin at
-(dims-1)/2 * spacing), eye = -forward * distance, view up = up, vertical view angle
2 atan(tan(fov/2) / zoom). Checked by the silhouettes of the converged images (mismatch in
pixels). The volumes are written as LPS-ordered raws (index axes = L, P, S), so no direction
matrix enters either renderer.

The same transfer function and shading: VTK's (the opacity and colour points of
../shared/peers/vtk_volume_bench.py, ambient 0.2, diffuse 0.7, specular 0.3, power 10, one
white headlight) written as a 3D Slicer .vp file that Voxray imports (--tf-file), opacity per 1 mm
on both sides; Voxray's light a point 100 m behind the eye (a headlight, as VTK's). mip: a grey
ramp over the window on both sides (VTK: colour ramp, opacity 1).

usage: equal_error.py --out DIR --cli VOXRAY_CLI --scene NAME=RAW:NX,NY,NZ:SX,SY,SZ [...]
       [--modes dvr,mip] [--steps 4,2,1,0.5,0.25] [--size 512x384] [--rounds 3] [--frames 3]
       [--device cpu|gpu] [--azimuth 30] [--elevation 15] [--zoom 1.3] [--fov 30]
       equal_error.py --out DIR --replot --cli - --scene - (pareto.png again from results.tsv)
"""
import argparse
import math
import os
import subprocess
import sys
import time

import numpy as np
# VTK's own modules only (not "import vtk", which loads all ~360 of its libraries): the GPU
# rows run on a machine where this script's VTK is a trimmed copy carried there.
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window and mappers)
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import VTK_SHORT, VTK_UNSIGNED_CHAR
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingVolume import vtkFixedPointVolumeRayCastMapper
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper

FINE = 1.0 / 16  # the converged images' step, voxels (the issue's 1/16)
# VTK's transfer function (../shared/peers/vtk_volume_bench.py, iso 400).
OPACITY = [(-1000, 0.0), (-100, 0.0), (40, 0.02), (400, 0.9), (3000, 1.0)]
COLOUR = [(-1000, 0, 0, 0), (0, 0.8, 0.5, 0.4), (400, 1, 1, 0.9), (3000, 1, 1, 1)]
AMBIENT, DIFFUSE, SPECULAR, POWER = 0.2, 0.7, 0.3, 10.0
MIP_WINDOW = (2000.0, 500.0)  # width, level in HU: -500 ... 1500


class Scene:
    def __init__(self, text):
        name, rest = text.split("=", 1)
        raw, dims, spacing = rest.rsplit(":", 2)
        self.name, self.raw = name, raw
        self.dims = [int(v) for v in dims.split(",")]
        self.spacing = [float(v) for v in spacing.split(",")]
        self.voxel_mm = min(self.spacing)


class Camera:
    """Voxray's makeViewGeometry for an LPS volume (direction = identity)."""

    def __init__(self, scene, a, width, height):
        az, el = math.radians(a.azimuth), math.radians(a.elevation)
        self.forward = np.array([-math.sin(az) * math.cos(el), math.cos(az) * math.cos(el),
                                 -math.sin(el)])
        right = np.array([math.cos(az), math.sin(az), 0.0])
        self.up = np.cross(right, self.forward)
        extent = np.array(scene.dims) * np.array(scene.spacing)
        radius = 0.5 * np.linalg.norm(extent)
        half = math.radians(0.5 * a.fov)
        self.distance = 1.05 * radius / math.sin(half)  # kFrameMargin
        self.eye = -self.forward * self.distance
        self.view_angle = 2.0 * math.degrees(math.atan(math.tan(half) / a.zoom))
        self.flags = ["--azimuth", str(a.azimuth), "--elevation", str(a.elevation), "--zoom",
                      str(a.zoom), "--fov", str(a.fov), "--projection", "perspective"]
        # A headlight: a point far behind the eye lights every sample from the view direction.
        self.light = -self.forward * 1e5


def write_vp(path):
    """VTK's transfer function and shading as a 3D Slicer volume property (.vp)."""
    op = [v for p in OPACITY for v in p]
    col = [v for p in COLOUR for v in p]
    lines = ["1", "1", str(DIFFUSE), str(AMBIENT), str(SPECULAR), str(POWER),
             " ".join(str(v) for v in [len(op)] + op), "4 0 1 255 1",
             " ".join(str(v) for v in [len(col)] + col)]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


class VtkRenderer:
    def __init__(self, scene, mode, width, height, cam, mapper):
        nx, ny, nz = scene.dims
        arr = np.fromfile(scene.raw, dtype="<i2")
        if arr.size != nx * ny * nz:
            sys.exit(f"{scene.raw}: {arr.size} voxels, expected {nx}x{ny}x{nz}")
        img = vtkImageData()
        img.SetDimensions(nx, ny, nz)
        img.SetSpacing(*scene.spacing)
        img.SetOrigin(*[-(n - 1) * 0.5 * s for n, s in zip(scene.dims, scene.spacing)])
        img.GetPointData().SetScalars(
            numpy_support.numpy_to_vtk(arr, deep=True, array_type=VTK_SHORT))
        self._keep = arr
        if mapper == "gpu":
            m = vtkOpenGLGPUVolumeRayCastMapper()
            m.SetAutoAdjustSampleDistances(0)
            m.SetLockSampleDistanceToInputSpacing(0)
            m.SetUseJittering(0)
        else:
            m = vtkFixedPointVolumeRayCastMapper()
            m.SetNumberOfThreads(os.cpu_count() or 1)
            m.SetImageSampleDistance(1.0)
            m.SetAutoAdjustSampleDistances(0)
        m.SetInputData(img)
        prop = vtkVolumeProperty()
        prop.SetInterpolationTypeToLinear()
        prop.SetScalarOpacityUnitDistance(1.0)
        ctf, otf = vtkColorTransferFunction(), vtkPiecewiseFunction()
        if mode == "dvr":
            for hu, r, g, b in COLOUR:
                ctf.AddRGBPoint(hu, r, g, b)
            for hu, a in OPACITY:
                otf.AddPoint(hu, a)
            prop.ShadeOn()
            prop.SetAmbient(AMBIENT)
            prop.SetDiffuse(DIFFUSE)
            prop.SetSpecular(SPECULAR)
            prop.SetSpecularPower(POWER)
            m.SetBlendModeToComposite()
        else:
            w, level = MIP_WINDOW
            ctf.AddRGBPoint(level - w / 2, 0, 0, 0)
            ctf.AddRGBPoint(level + w / 2, 1, 1, 1)
            otf.AddPoint(-32768, 1.0)
            otf.AddPoint(32767, 1.0)
            m.SetBlendModeToMaximumIntensity()
        prop.SetColor(ctf)
        prop.SetScalarOpacity(otf)
        vol = vtkVolume()
        vol.SetMapper(m)
        vol.SetProperty(prop)
        ren = vtkRenderer()
        ren.AddVolume(vol)
        ren.SetBackground(0, 0, 0)
        # VTK's automatic headlight has a black ambient colour, which zeroes the property's
        # ambient term; this one is white, so that ambient 0.2 means in VTK what it means in
        # Voxray (and in the .vp file) and the two shade alike.
        light = vtkLight()
        light.SetLightTypeToHeadlight()
        light.SetAmbientColor(1, 1, 1)
        light.SetDiffuseColor(1, 1, 1)
        light.SetSpecularColor(1, 1, 1)
        light.SetIntensity(1.0)
        ren.AddLight(light)
        rw = vtkRenderWindow()
        rw.SetOffScreenRendering(1)
        rw.AddRenderer(ren)
        rw.SetSize(width, height)
        c = ren.GetActiveCamera()
        c.SetFocalPoint(0, 0, 0)
        c.SetPosition(*cam.eye)
        c.SetViewUp(*cam.up)
        c.SetViewAngle(cam.view_angle)
        ren.ResetCameraClippingRange()
        self.m, self.rw, self.ren = m, rw, ren
        rw.Initialize()  # the OpenGL context, so that its renderer string can be read
        self.gl = rw.ReportCapabilities()

    def frames(self, step_mm, n):
        # The first render (upload, gradient encoding, shaders) came with image(): not timed.
        self.m.SetSampleDistance(step_mm)
        t = []
        for _ in range(n):
            self.ren.Modified()
            t0 = time.perf_counter()
            self.rw.Render()
            self.rw.WaitForCompletion()
            t.append((time.perf_counter() - t0) * 1e3)
        return t

    def image(self, step_mm):
        self.m.SetSampleDistance(step_mm)
        self.rw.Render()
        w2i = vtkWindowToImageFilter()
        w2i.SetInput(self.rw)
        w2i.SetInputBufferTypeToRGB()
        w2i.ReadFrontBufferOff()
        w2i.Update()
        out = w2i.GetOutput()
        w, h, _ = out.GetDimensions()
        rgb = numpy_support.vtk_to_numpy(out.GetPointData().GetScalars()).reshape(h, w, -1)
        return rgb[::-1, :, :3].copy()  # VTK's rows run bottom to top


def voxray_args(a, scene, mode, cam, vp, size, step_mm):
    nx, ny, _ = scene.dims
    args = [a.cli, "render", scene.raw, "--raw-dims", f"{nx},{ny}", "--raw-type", "i16",
            "--raw-spacing", ",".join(str(s) for s in scene.spacing), "--size", size,
            "--background", "0,0,0", "--step", repr(step_mm)] + cam.flags
    if mode == "dvr":
        args += ["--tf-file", vp, "--opacity-unit", "1",
                 "--light", ",".join(repr(float(v)) for v in cam.light)]
    else:
        args += ["--mode", "mip", "--window", f"{MIP_WINDOW[0]},{MIP_WINDOW[1]}"]
    return args


def run(args):
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(args)}\nfailed ({r.returncode}): {r.stderr.strip()}")
    return r.stdout


def voxray_frames(a, base, n, png):
    """Each timed frame's wall time (ms), as VTK's: the median is then over all rounds' frames."""
    out = run(base + ["--device", a.device, "--repeat", str(n), "-o", png])
    for line in out.splitlines():
        if line.startswith("frames ") and " each " in line:  # "frames N ms median M ... each t..."
            return [float(t) for t in line.split(" each ")[1].split()]
    sys.exit(f"voxray-cli render --repeat printed no frame times: {out}")


def read_rgb(path):
    """PNG through VTK's reader (libpng): the same pixels skimage read, with no skimage needed
    where the images are made (--no-score)."""
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    out = r.GetOutput()
    w, h, _ = out.GetDimensions()
    if w * h == 0:
        sys.exit(f"{path}: not a readable PNG")
    px = numpy_support.vtk_to_numpy(out.GetPointData().GetScalars()).reshape(h, w, -1)
    return px[::-1, :, :3].copy()  # VTK's rows run bottom to top


def save_png(path, rgb):
    h, w, _ = rgb.shape
    img = vtkImageData()
    img.SetDimensions(w, h, 1)
    flat = np.ascontiguousarray(rgb[::-1, :, :3]).reshape(-1, 3)
    img.GetPointData().SetScalars(
        numpy_support.numpy_to_vtk(flat, deep=True, array_type=VTK_UNSIGNED_CHAR))
    wr = vtkPNGWriter()
    wr.SetFileName(path)
    wr.SetInputData(img)
    wr.Write()


def score(img, ref):
    if ref is None:
        return math.nan, math.nan  # --no-score: the images and times only
    if np.array_equal(img, ref):
        return 99.0, 1.0  # identical: PSNR capped as Voxray's accuracy sweep caps it
    from skimage.metrics import peak_signal_noise_ratio, structural_similarity
    psnr = peak_signal_noise_ratio(ref, img, data_range=255)
    # Wang et al. 2004: Gaussian window sigma 1.5, population covariances, per channel.
    ssim = structural_similarity(ref, img, data_range=255, channel_axis=2, gaussian_weights=True,
                                 sigma=1.5, use_sample_covariance=False)
    return psnr, ssim


def silhouette(a_img, b_img, out_png):
    """Mismatch of the two silhouettes (pixels that are not background): pixels covered by
    one only, and the distance (pixels) from each outline pixel to the other's outline. A pixel
    counts as covered above 20 of 255 levels: below that lie the faint fringes where the two
    reconstructions' last few percent of opacity differ, which say nothing about the camera."""
    from scipy import ndimage
    ma, mb = a_img.max(axis=2) > 20, b_img.max(axis=2) > 20
    edge = lambda m: m & ~ndimage.binary_erosion(m)
    ea, eb = edge(ma), edge(mb)
    da = ndimage.distance_transform_edt(~eb)[ea]
    db = ndimage.distance_transform_edt(~ea)[eb]
    d = np.concatenate([da, db]) if da.size and db.size else np.array([np.inf])
    over = np.zeros(ma.shape + (3,), np.uint8)
    over[ma & mb] = (255, 255, 255)
    over[ma & ~mb] = (255, 0, 0)
    over[mb & ~ma] = (0, 255, 0)
    save_png(out_png, over)
    return int((ma ^ mb).sum()), float(np.mean(d)), float(np.max(d))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--cli", required=True)
    ap.add_argument("--scene", action="append", required=True)
    ap.add_argument("--modes", default="dvr,mip")
    ap.add_argument("--steps", default="4,2,1,0.5,0.25")
    # dvr only: Voxray with pre-integrated classification (--preintegrate on), its own rows
    # ("Voxray preint"), scored against the same converged image and reference.
    ap.add_argument("--preint-steps", default="")
    # Every mode: Voxray with image-space adaptive sampling (--adaptive-image T,K), each
    # setting of this ';'-separated list its own rows ("Voxray adaptive T,K") at
    # --adaptive-steps (default: the steps above), scored as the others.
    ap.add_argument("--adaptive-image", default="")
    ap.add_argument("--adaptive-steps", default="")
    ap.add_argument("--size", default="512x384")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--frames", type=int, default=3)
    ap.add_argument("--device", default="cpu", choices=["cpu", "gpu"])
    ap.add_argument("--azimuth", type=float, default=30.0)
    ap.add_argument("--elevation", type=float, default=15.0)
    ap.add_argument("--zoom", type=float, default=1.3)
    ap.add_argument("--fov", type=float, default=30.0)
    ap.add_argument("--replot", action="store_true",
                    help="only draw pareto.png again from the results.tsv in --out")
    # The GPU rows: the machine with the GPU has VTK but not scikit-image or scipy, and its
    # CPU time is scarce. --no-score there renders and times only (no reference, no scores);
    # --rescore here scores those images with the times of that run's results.tsv.
    ap.add_argument("--no-score", action="store_true")
    ap.add_argument("--rescore", action="store_true")
    a = ap.parse_args()
    if a.replot:
        replot(a)
        return
    os.makedirs(a.out, exist_ok=True)
    width, height = (int(v) for v in a.size.lower().split("x"))
    steps = [float(s) for s in a.steps.split(",")]
    preint_steps = [float(s) for s in a.preint_steps.split(",") if s]
    adaptive = [s for s in a.adaptive_image.split(";") if s]
    adaptive_steps = [float(s) for s in (a.adaptive_steps or a.steps).split(",") if s]
    vp = os.path.join(a.out, "vtk-tf.vp")
    write_vp(vp)
    timed = read_times(a.out) if a.rescore else {}
    rows, notes = [], []
    log = lambda s: print(s, file=sys.stderr, flush=True)
    for scene_text in a.scene:
        scene = Scene(scene_text)
        cam = Camera(scene, a, width, height)
        for mode in a.modes.split(","):
            tag = f"{scene.name}-{mode}"
            c = Case(a, scene, mode, cam, vp, tag)
            psteps = preint_steps if mode == "dvr" else []
            if a.rescore:
                vtk_name = next((k[2] for k in timed if k[:2] == (scene.name, mode) and
                                 k[2].startswith("VTK")), None)
                if vtk_name is None:
                    sys.exit(f"{a.out}/results.tsv has no VTK rows for {tag}")
                times = {(r, s): [timed[(scene.name, mode, n, s)]]
                         for r, n, ss in (("vtk", vtk_name, steps), ("voxray", "Voxray", steps),
                                          ("preint", "Voxray preint", psteps))
                         for s in ss}
                times.update({(t, s): [timed[(scene.name, mode, f"Voxray adaptive {t}", s)]]
                              for t in adaptive for s in adaptive_steps})
            else:
                vtk_name, times = c.render_and_time(steps, psteps, adaptive, adaptive_steps, log)
            rows += c.score_rows(vtk_name, times, steps, psteps, adaptive, adaptive_steps, notes,
                                 log)
    write_results(a, rows, notes)


def read_times(out):
    """(scene, mode, renderer, step) -> the median ms of an earlier run's results.tsv."""
    import csv
    with open(os.path.join(out, "results.tsv")) as f:
        return {(r["scene"], r["mode"], r["renderer"], float(r["step_voxels"])):
                float(r["ms_median"]) for r in csv.DictReader(f, delimiter="\t")}


class Case:
    """One scene and mode: its images (named by tag, step and technique), made and timed, or
    read back and scored."""

    def __init__(self, a, scene, mode, cam, vp, tag):
        self.a, self.scene, self.mode, self.cam, self.tag = a, scene, mode, cam, tag
        self.base = lambda s: voxray_args(a, scene, mode, cam, vp, a.size, s * scene.voxel_mm)

    def png(self, what, step=None):
        tail = "" if step is None else f"-{step:g}"
        return os.path.join(self.a.out, f"{self.tag}-{what}{tail}.png")

    def adaptive_png(self, t, s):
        return self.png(f"adaptive{t.replace(',', '_')}", s)

    def ai_args(self, s, t):
        return self.base(s) + ["--adaptive-image", t]

    def pre(self, s):
        return self.base(s) + ["--preintegrate", "on"]

    def render_and_time(self, steps, psteps, adaptive, adaptive_steps, log):
        a, tag = self.a, self.tag
        width, height = (int(v) for v in a.size.lower().split("x"))
        mapper = "gpu" if a.device == "gpu" else "fixed"
        vr = VtkRenderer(self.scene, self.mode, width, height, self.cam, mapper)
        gl = next((l for l in vr.gl.splitlines() if "renderer string" in l), "")
        log(f"{tag}: VTK's {gl.strip() or 'OpenGL renderer unknown'}")
        if a.device == "gpu" and (not gl or "llvmpipe" in gl or "softpipe" in gl):
            log(f"{tag}: no GPU OpenGL context: VTK's GPU mapper skipped, VTK rows are its CPU "
                "ray caster")
            vr = VtkRenderer(self.scene, self.mode, width, height, self.cam, "fixed")
            mapper = "fixed"
        vtk_name = "VTK " + ("GPU" if mapper == "gpu" else "fixed-point")
        log(f"{tag}: converged images")
        save_png(self.png("vtk-fine"), vr.image(FINE * self.scene.voxel_mm))
        run(self.base(FINE) + ["--device", a.device, "-o", self.png("voxray-fine")])
        # Timed frames, VTK and Voxray taking turns each round.
        times = {(r, s): [] for r in ("vtk", "voxray") for s in steps}
        times.update({("preint", s): [] for s in psteps})
        times.update({(t, s): [] for t in adaptive for s in adaptive_steps})
        for rnd in range(a.rounds):
            for s in steps:
                times[("vtk", s)] += vr.frames(s * self.scene.voxel_mm, a.frames)
                times[("voxray", s)] += voxray_frames(a, self.base(s), a.frames,
                                                      self.png("voxray", s))
            for s in psteps:
                times[("preint", s)] += voxray_frames(a, self.pre(s), a.frames,
                                                      self.png("preint", s))
            for t in adaptive:
                for s in adaptive_steps:
                    times[(t, s)] += voxray_frames(a, self.ai_args(s, t), a.frames,
                                                   self.adaptive_png(t, s))
            log(f"{tag}: round {rnd + 1} of {a.rounds}")
        for s in steps:
            save_png(self.png("vtk", s), vr.image(s * self.scene.voxel_mm))
        del vr
        return vtk_name, times

    def reference(self):
        ref_png = self.png("reference")
        # Minutes on a CPU: kept between runs into the same folder, beside the command that
        # made it, and made again when this run's command differs.
        ref_cmd = " ".join(self.base(FINE) + ["--reference", "-o", ref_png])
        made = open(ref_png + ".cmd").read() if os.path.exists(ref_png + ".cmd") else ""
        if not os.path.exists(ref_png) or made != ref_cmd:
            run(self.base(FINE) + ["--reference", "-o", ref_png])
            with open(ref_png + ".cmd", "w") as f:
                f.write(ref_cmd)
        return read_rgb(ref_png)

    def score_rows(self, vtk_name, times, steps, psteps, adaptive, adaptive_steps, notes, log):
        a, tag, scene, mode = self.a, self.tag, self.scene, self.mode
        width, height = (int(v) for v in a.size.lower().split("x"))
        vtk_fine, vox_fine = read_rgb(self.png("vtk-fine")), read_rgb(self.png("voxray-fine"))
        ref, own = None, {}
        if not a.no_score:
            log(f"{tag}: the double-precision reference")
            ref = self.reference()
            own = {"vtk": vtk_fine, "voxray": vox_fine}
            mis, mean_d, max_d = silhouette(vtk_fine, vox_fine, self.png("silhouettes"))
            notes.append(f"{tag}: silhouettes of the converged images: {mis} pixels covered by "
                         f"one renderer only of {width * height}; outline distance mean "
                         f"{mean_d:.2f} px, max {max_d:.2f} px")
        images = [(vtk_name, "vtk", s, self.png("vtk", s)) for s in steps]
        images += [("Voxray", "voxray", s, self.png("voxray", s)) for s in steps]
        images += [("Voxray preint", "preint", s, self.png("preint", s)) for s in psteps]
        images += [(f"Voxray adaptive {t}", t, s, self.adaptive_png(t, s))
                   for t in adaptive for s in adaptive_steps]
        rows = []
        for name, key, s, path in images:
            img = read_rgb(path)
            po, so = score(img, own.get("vtk" if key == "vtk" else "voxray"))
            pr, sr = score(img, ref)
            rows.append(dict(scene=scene.name, mode=mode, renderer=name, step=s,
                             ms=float(np.median(times[(key, s)])), psnr_own=po, ssim_own=so,
                             psnr_ref=pr, ssim_ref=sr))
        if ref is not None:
            # The converged images against the reference: each renderer's own error floor.
            for name, img in ((vtk_name, vtk_fine), ("Voxray", vox_fine)):
                pr, sr = score(img, ref)
                notes.append(f"{tag}: {name} at 1/16 voxel against Voxray's reference: "
                             f"PSNR {pr:.2f} dB, SSIM {sr:.4f}")
        return rows


def cheapest(rows, key, target):
    """The least time among ROWS whose KEY reaches TARGET; None when none does."""
    ok = [r["ms"] for r in rows if r[key] >= target]
    return min(ok) if ok else None


def ratios(rows, voxray="Voxray"):
    """VTK's time over Voxray's cheapest time to the same error, at VTK's 0.5-voxel step and
    at VTK's best error, per error measure; '>=' when even Voxray's coarsest step is better
    (the true ratio is larger). VOXRAY names the Voxray rows ("Voxray", "Voxray preint", or
    "both": the cheaper of the two at each error)."""
    out = []
    vtk_rows = [r for r in rows if not r["renderer"].startswith("Voxray")]
    vox_rows = [r for r in rows if r["renderer"].startswith("Voxray") and
                (voxray == "both" or r["renderer"] == voxray)]
    if not vox_rows:
        return out
    coarsest = max(r["step"] for r in vox_rows)
    for key, what in (("psnr_own", "own converged image"), ("psnr_ref", "Voxray's reference")):
        best = max(vtk_rows, key=lambda r: (r[key], -r["ms"]))
        half = [r for r in vtk_rows if r["step"] == 0.5]
        for label, v in (("VTK at 0.5 voxel", half[0] if half else None),
                         ("VTK's best error", best)):
            if v is None:
                continue
            ms = cheapest(vox_rows, key, v[key])
            if ms is None:
                out.append(f"{label} ({v[key]:.2f} dB vs {what}, {v['ms']:.1f} ms): Voxray "
                           "does not reach it at these steps")
                continue
            at_coarsest = any(r["ms"] == ms and r["step"] == coarsest for r in vox_rows)
            out.append(f"{label} ({v[key]:.2f} dB vs {what}, step {v['step']:g}, "
                       f"{v['ms']:.1f} ms): Voxray {ms:.1f} ms, ratio "
                       f"{'>= ' if at_coarsest else ''}{v['ms'] / ms:.2f}")
    return out


def write_results(a, rows, notes):
    cols = ["scene", "mode", "renderer", "step_voxels", "ms_median", "psnr_own_db", "ssim_own",
            "psnr_ref_db", "ssim_ref"]
    with open(os.path.join(a.out, "results.tsv"), "w") as f:
        f.write("\t".join(cols) + "\n")
        for r in rows:
            f.write("\t".join([r["scene"], r["mode"], r["renderer"], f"{r['step']:g}",
                               f"{r['ms']:.1f}", f"{r['psnr_own']:.2f}", f"{r['ssim_own']:.4f}",
                               f"{r['psnr_ref']:.2f}", f"{r['ssim_ref']:.4f}"]) + "\n")
    with open("/proc/loadavg") as f:
        load = f.read().split()[:3]
    lines = [f"# {a.size}, device {a.device}, {a.rounds} rounds x {a.frames} frames (medians), "
             f"load after the run {' '.join(load)}",
             "| scene | mode | renderer | step (voxels) | ms | PSNR own (dB) | SSIM own | "
             "PSNR ref (dB) | SSIM ref |", "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['scene']} | {r['mode']} | {r['renderer']} | {r['step']:g} | "
                     f"{r['ms']:.1f} | {r['psnr_own']:.2f} | {r['ssim_own']:.4f} | "
                     f"{r['psnr_ref']:.2f} | {r['ssim_ref']:.4f} |")
    lines.append("")
    if a.no_score:  # the times and images only: --rescore makes the table and the plot
        with open(os.path.join(a.out, "table.md"), "w") as f:
            f.write("\n".join(lines) + "\n")
        return
    cases = sorted({(r["scene"], r["mode"]) for r in rows})
    for sc, mode in cases:
        case_rows = [r for r in rows if r["scene"] == sc and r["mode"] == mode]
        names = ["Voxray"]
        others = sorted({r["renderer"] for r in case_rows
                         if r["renderer"].startswith("Voxray ")})
        if others:  # each technique alone, and "both": every Voxray row together
            names += others + ["both"]
        for name in names:
            for line in ratios(case_rows, name):
                label = "" if name == "Voxray" else f" [{name}]"
                lines.append(f"- {sc} {mode}{label}: {line}")
    lines += [f"- {n}" for n in notes]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(a.out, "table.md"), "w") as f:
        f.write(text)
    print(text)
    plot(a, rows, cases)


def replot(a):
    import csv
    with open(os.path.join(a.out, "results.tsv")) as f:
        rows = [dict(scene=r["scene"], mode=r["mode"], renderer=r["renderer"],
                     step=float(r["step_voxels"]), ms=float(r["ms_median"]),
                     psnr_own=float(r["psnr_own_db"]), psnr_ref=float(r["psnr_ref_db"]))
                for r in csv.DictReader(f, delimiter="\t")]
    plot(a, rows, sorted({(r["scene"], r["mode"]) for r in rows}))


def plot(a, rows, cases):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, len(cases), figsize=(4.2 * len(cases), 7.5), squeeze=False)
    for col, (sc, mode) in enumerate(cases):
        for row, (key, what) in enumerate((("psnr_own", "vs own 1/16-voxel image"),
                                           ("psnr_ref", "vs Voxray's reference"))):
            ax = axes[row][col]
            for name in sorted({r["renderer"] for r in rows}):
                # In step order: the curve is the trade as the step shrinks (a time that
                # noise made longer for a coarser step shows as a back-turn, not hidden).
                rs = sorted((r for r in rows if (r["scene"], r["mode"], r["renderer"]) ==
                             (sc, mode, name)), key=lambda r: -r["step"])
                ax.plot([r["ms"] for r in rs], [r[key] for r in rs], "o-", label=name)
                for r in rs:
                    ax.annotate(f"{r['step']:g}", (r["ms"], r[key]), fontsize=7,
                                xytext=(3, 3), textcoords="offset points")
            ax.set_xscale("log")
            ax.set_xlabel("ms per frame (median)")
            ax.set_ylabel(f"PSNR (dB) {what}")
            ax.set_title(f"{sc} {mode}", fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
    fig.suptitle(f"Speed at equal error, {a.size}, device {a.device} (labels: step in voxels)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "pareto.png"), dpi=90)


if __name__ == "__main__":
    main()
