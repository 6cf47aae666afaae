#!/usr/bin/env python3
"""Hostile-input corpus for voxray-cli (issue 39): mutated real DICOM, hostile research-format
headers, raw flags, session files and hostile PACS servers, each run under the caps a user's
machine would impose (4 GiB address space, 30 s). Not part of CI's time budget.

Usage: tests/hostile/mutation_corpus.py BUILD_DIR [--cases N] [--seed S] [--family F ...]

Every case ends in one of: handled (exit 0, or 1 with a message), internal (exit 3: an
exception other than voxray::Error reached main), crash (a signal), hang (over 30 s), oom
(the cap reached: bad_alloc or "out of memory"). Prints the counts per family and every case
that was not handled, with the command to repeat it; exits 1 if any was not handled.
"""
import argparse
import http.server
import json
import os
import random
import shutil
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared", "data"))
CAP_BYTES = 4 << 30
CAP_SECONDS = 30


def run(cli, args, work):
    """One case: voxray-cli ARGS under the caps; returns (outcome, exit code, output tail)."""
    cmd = ["prlimit", f"--as={CAP_BYTES}", "--", cli] + args
    env = dict(os.environ, HOME=work, XDG_CACHE_HOME=os.path.join(work, "cache"))
    try:
        p = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True, timeout=CAP_SECONDS,
                           env=env, cwd=work)
    except subprocess.TimeoutExpired:
        return "hang", None, ""
    out = (p.stdout + p.stderr).decode("utf-8", "replace")
    if "bad_alloc" in out or "out of memory" in out.lower():
        return "oom", p.returncode, out[-300:]
    if p.returncode < 0:
        return "crash", p.returncode, out[-300:]
    if p.returncode == 0 or (p.returncode in (1, 2) and out.strip()):
        return "handled", p.returncode, ""
    return "internal", p.returncode, out[-300:]


# ---- DICOM: mutations of real files -----------------------------------------------------

def dicom_seeds():
    seeds = []
    for root, _, files in os.walk(os.path.join(DATA, "dicom")):
        for f in sorted(files):
            path = os.path.join(root, f)
            if f.endswith(".dcm") and os.path.getsize(path) < 4 << 20:
                seeds.append(path)
    return seeds


def mutate_bytes(rng, data):
    b = bytearray(data)
    op = rng.randrange(6)
    if op == 0:  # flip bytes
        for _ in range(rng.randint(1, 16)):
            b[rng.randrange(len(b))] ^= 1 << rng.randrange(8)
    elif op == 1:  # truncate
        del b[rng.randrange(132, len(b)):]
    elif op == 2:  # a length field (after a tag and VR) made huge or odd
        at = rng.randrange(132, max(133, len(b) - 8))
        b[at:at + 4] = struct.pack("<I", rng.choice([0xFFFFFFFF, 0xFFFFFFFE, 0x7FFFFFFF, 1, 3]))
    elif op == 3:  # a chunk repeated
        at, n = rng.randrange(132, len(b)), rng.randint(1, 4096)
        b[at:at] = b[at:at + n] * rng.randint(2, 64)
    elif op == 4:  # a VR swapped for another
        at = rng.randrange(132, max(133, len(b) - 2))
        b[at:at + 2] = rng.choice([b"SQ", b"OB", b"UN", b"US", b"FD", b"UT", b"XX"])
    else:  # transfer syntax UID replaced
        i = b.find(b"1.2.840.10008.1.2")
        if i > 0:
            ts = rng.choice([b"1.2.840.10008.1.2.4.90", b"1.2.840.10008.1.2.5\0",
                             b"1.2.840.10008.1.2.2\0", b"9.9.9.9.9.9.9.9.9\0"])
            b[i:i + len(ts)] = ts
    return bytes(b)


def dicom_cases(rng, n, work):
    seeds = dicom_seeds()
    for k in range(n):
        seed = rng.choice(seeds)
        data = open(seed, "rb").read()
        for _ in range(rng.randint(1, 3)):
            data = mutate_bytes(rng, data)
        path = os.path.join(work, f"case{k}.dcm")
        open(path, "wb").write(data)
        yield f"{os.path.relpath(seed, DATA)} mutated", ["info", "--json", path], path


# ---- Research formats: NIfTI, NRRD, MetaImage ----------------------------------------------

def nifti_header(rng, dims, datatype, bitpix, vox_offset):
    h = bytearray(348)
    struct.pack_into("<i", h, 0, 348)
    struct.pack_into("<8h", h, 40, *dims)
    struct.pack_into("<hh", h, 70, datatype, bitpix)
    struct.pack_into("<8f", h, 76, 1, *[rng.choice([1.0, 0.0, -1.0, 1e30, float("nan")])
                                        for _ in range(3)], 1, 1, 1, 1)
    struct.pack_into("<f", h, 108, vox_offset)
    struct.pack_into("<ff", h, 112, rng.choice([1.0, 0.0, float("inf")]), 0.0)
    struct.pack_into("<hh", h, 252, rng.randint(0, 3), rng.randint(0, 3))
    h[344:348] = b"n+1\0"
    return bytes(h)


def format_cases(rng, n, work):
    big = [0, 1, 2, 3, 64, 32767, -1, -32768]
    for k in range(n):
        kind = k % 3
        path = os.path.join(work, f"case{k}")
        os.makedirs(path, exist_ok=True)
        if kind == 0:
            dims = [rng.choice([3, 4, 7, 8, -1, 0])] + [rng.choice(big + [4, 8]) for _ in range(7)]
            dt, bp = rng.choice([(4, 16), (2, 8), (16, 32), (64, 64), (128, 24), (4, 8), (0, 0),
                                 (32767, 16)])
            off = rng.choice([352.0, 0.0, -1.0, 1e20, 351.0, float("nan")])
            body = bytes(rng.randrange(256) for _ in range(rng.choice([0, 4, 256, 4096])))
            f = os.path.join(path, "v.nii")
            open(f, "wb").write(nifti_header(rng, dims, dt, bp, off) + b"\0" * 4 + body)
        elif kind == 1:
            sizes = " ".join(str(rng.choice([1, 2, 4, 8, 0, -3, 2**31, 10**12])) for _ in range(3))
            lines = ["NRRD0004", "type: " + rng.choice(["short", "uchar", "float", "double",
                                                        "block", "int64", "???"]),
                     "dimension: " + rng.choice(["3", "2", "4", "0", "99", "-1"]),
                     "sizes: " + sizes,
                     "encoding: " + rng.choice(["raw", "gzip", "bzip2", "ascii", "hex", "zz"]),
                     "endian: little",
                     "space: " + rng.choice(["left-posterior-superior", "RAS", "scanner-xyz", "x"]),
                     "space directions: " + rng.choice(["(1,0,0) (0,1,0) (0,0,1)", "none (1,0,0)",
                                                        "(nan,0,0) (0,0,0) (0,0,1)", "(1,0,0)"])]
            datafile = rng.choice([
                None, "data.raw", "/etc/passwd", "../../etc/hostname", "/proc/self/environ",
                "slice%03d.raw 0 2147483647 1", "slice%0999999d.raw 0 5 1", "slice%d%s.raw 0 3 1",
                "LIST", "link.raw", "slice%03d.raw 5 0 -1", "fifo.raw"])
            if datafile == "link.raw":
                os.symlink("/etc/hostname", os.path.join(path, "link.raw"))
            if datafile == "fifo.raw":
                os.mkfifo(os.path.join(path, "fifo.raw"))
            open(os.path.join(path, "data.raw"), "wb").write(b"\1\0" * 64)
            for _ in range(rng.choice([0, 0, 10, 5000, 50000])):
                lines.append(f"key{rng.randrange(10**6)}:={'x' * rng.randrange(40)}")
            if datafile == "LIST":
                lines += ["data file: LIST", "data.raw", "/etc/passwd", "data.raw"]
            elif datafile:
                lines.append("data file: " + datafile)
            text = "\n".join(lines) + "\n"
            f = os.path.join(path, "v.nhdr" if datafile else "v.nrrd")
            open(f, "w").write(text + ("" if datafile else "\n") + ("\1\0" * rng.choice([0, 8, 64])
                                                                   if not datafile else ""))
        else:
            lines = ["ObjectType = Image", "NDims = " + rng.choice(["3", "2", "0", "-4", "9999"]),
                     "DimSize = " + " ".join(str(rng.choice([4, 1, 0, -2, 2**40])) for _ in range(3)),
                     "ElementType = " + rng.choice(["MET_SHORT", "MET_UCHAR", "MET_DOUBLE", "MET_X"]),
                     "ElementSpacing = " + rng.choice(["1 1 1", "0 0 0", "nan 1 1", "-1 2 3"]),
                     "TransformMatrix = " + rng.choice(["1 0 0 0 1 0 0 0 1", "0 0 0 0 0 0 0 0 0",
                                                        "1 2"]),
                     "CompressedData = " + rng.choice(["False", "True"]),
                     "ElementDataFile = " + rng.choice(["LOCAL", "v.raw", "/etc/passwd",
                                                        "../../../etc/hostname", "v%03d.raw 0 99999999 1",
                                                        "LIST"])]
            open(os.path.join(path, "v.raw"), "wb").write(b"\2\0" * 64)
            f = os.path.join(path, "v.mha")
            open(f, "wb").write(("\n".join(lines) + "\n").encode() + b"\3\0" * rng.choice([0, 64]))
        yield f"format kind {kind}", ["info", "--json", f], path


# ---- Raw flags ------------------------------------------------------------------------------

def raw_cases(rng, n, work):
    raw = os.path.join(work, "r.raw")
    open(raw, "wb").write(bytes(rng.randrange(256) for _ in range(4096)))
    vals = ["0", "1", "-1", "64", "2147483647", "4294967297", "1e9", "x", "", "3.5"]
    for k in range(n):
        dims = ",".join(rng.choice(vals) for _ in range(rng.choice([2, 3, 4])))
        args = ["info", raw, "--raw-dims", dims, "--raw-type", rng.choice(["u8", "i16", "u16",
                                                                           "f32", "q9"])]
        if rng.random() < 0.5:
            args += ["--raw-offset", rng.choice(vals)]
        if rng.random() < 0.5:
            args += ["--raw-spacing", ",".join(rng.choice(["1", "0", "-1", "nan", "inf", "1e308"])
                                               for _ in range(3))]
        if rng.random() < 0.3:
            args += ["--raw-rescale", rng.choice(["1,0", "0,0", "nan,1", "1e308,1e308"])]
        yield "raw flags", args, None


# ---- Sessions -------------------------------------------------------------------------------

def session_cases(rng, n, work):
    base = {"version": 1, "input": "", "quality": "interactive", "view": {"width": 16,
                                                                          "height": 16}}
    values = [None, True, -1, 0, 1e308, float("nan"), "x" * 100000, "\u001b[2J", [], {},
              [[[[[]]]]], "\xff", 2**63, -2**63]
    for k in range(n):
        doc = json.loads(json.dumps(base))
        for _ in range(rng.randint(1, 6)):
            key = rng.choice(["version", "input", "quality", "view", "params", "camera", "clip",
                              "window", "tf", "light", "unknown%d" % rng.randrange(99)])
            doc[key] = rng.choice(values)
        text = json.dumps(doc, allow_nan=True)
        if rng.random() < 0.2:  # broken JSON
            text = text[:rng.randrange(len(text))]
        if rng.random() < 0.1:  # many keys
            text = "{" + ",".join(f'"k{i}":{i}' for i in range(rng.choice([2000, 300000]))) + "}"
        if rng.random() < 0.1:  # deep nesting
            d = rng.choice([300, 100000])
            text = "[" * d + "]" * d
        path = os.path.join(work, f"s{k}.voxray-session")
        open(path, "w", encoding="utf-8", errors="surrogateescape").write(text)
        yield "session", ["render", "--session", path, "-o", os.path.join(work, f"s{k}.png"),
                          "--size", "16x16"], path


# ---- PACS: hostile DICOMweb servers -----------------------------------------------------

class Hostile(http.server.BaseHTTPRequestHandler):
    behaviour = "ok"

    def log_message(self, *a):
        pass

    def do_GET(self):
        b = Hostile.behaviour
        try:
            if b == "huge-length":
                self.send_response(200)
                self.send_header("Content-Type", "application/dicom+json")
                self.send_header("Content-Length", str(10**12))
                self.end_headers()
                for _ in range(200):
                    self.wfile.write(b"[" * 65536)
            elif b == "endless":
                self.send_response(200)
                self.send_header("Content-Type", "application/dicom+json")
                self.end_headers()
                t = time.time()
                while time.time() - t < 40:
                    self.wfile.write(b"[{}," * 16384)
            elif b == "slow-loris":
                self.send_response(200)
                self.end_headers()
                t = time.time()
                while time.time() - t < 40:
                    self.wfile.write(b"[")
                    self.wfile.flush()
                    time.sleep(0.5)
            elif b == "garbage-json":
                body = random.choice([b"{", b"[1,2", b"\xff\xfe", b"[{\"00100010\":{\"vr\":\"PN\",\"Value\":[{\"Alphabetic\":\"\x1b[2J\"}]}}]",
                                      b"[{\"00201206\":{\"vr\":\"IS\",\"Value\":[1.5e300]}}]"])
                self.send_response(200)
                self.send_header("Content-Type", "application/dicom+json")
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)
            elif b == "redirect":
                self.send_response(302)
                self.send_header("Location", "http://127.0.0.1:1/")
                self.send_header("Content-Length", "0")
                self.end_headers()
            elif b == "same-page":
                body = json.dumps([{"0020000D": {"vr": "UI", "Value": ["1.2.3"]}}] * 100).encode()
                self.send_response(200)
                self.send_header("Content-Type", "application/dicom+json")
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)
            elif b == "bad-multipart":
                body = b"--x\r\nContent-Type: application/dicom\r\n\r\n" + b"\0" * 1000 + b"--y--"
                self.send_response(200)
                self.send_header("Content-Type", 'multipart/related; type="application/dicom"; boundary=x')
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)
            else:
                self.send_response(404)
                self.send_header("Content-Length", "0")
                self.end_headers()
        except (BrokenPipeError, ConnectionResetError):
            pass


def pacs_cases(rng, n, work):
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Hostile)
    server.daemon_threads = True
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = f"http://127.0.0.1:{server.server_address[1]}/dicom-web"
    # A named node with a short timeout, in the case's own configuration folder (HOME=work).
    config = os.path.join(work, ".config", "voxray")
    os.makedirs(config, exist_ok=True)
    with open(os.path.join(config, "pacs-nodes.json"), "w") as f:
        json.dump({"nodes": {"hostile": {"url": url, "timeout": 5}}}, f)
    behaviours = ["huge-length", "endless", "slow-loris", "garbage-json", "redirect",
                  "same-page", "bad-multipart", "404"]
    try:
        for k in range(n):
            Hostile.behaviour = behaviours[k % len(behaviours)]
            cmd = rng.choice([["pacs", "echo", "hostile"], ["pacs", "find", "hostile"],
                              ["pacs", "find", "hostile", "--name", "DOE*", "--id", "P1"],
                              ["pacs", "find", "hostile", "--level", "series", "--study", "1.2"],
                              ["pacs", "get", "hostile", "--study", "1.2.3", "--series",
                               "1.2.3.4", "--cache", os.path.join(work, "cache")]])
            yield f"pacs {Hostile.behaviour}", cmd, None
    finally:
        server.shutdown()


FAMILIES = {"dicom": dicom_cases, "formats": format_cases, "raw": raw_cases,
            "sessions": session_cases, "pacs": pacs_cases}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--cases", type=int, default=500, help="cases per family")
    ap.add_argument("--seed", type=int, default=39)
    ap.add_argument("--family", action="append", choices=sorted(FAMILIES))
    a = ap.parse_args()
    cli = os.path.abspath(os.path.join(a.build, "bin", "voxray-cli"))
    counts, bad = {}, []
    for fam in a.family or sorted(FAMILIES):
        rng = random.Random(a.seed)
        work = tempfile.mkdtemp(prefix=f"voxray-hostile-{fam}-")
        c = counts.setdefault(fam, {})
        try:
            for what, args, keep in FAMILIES[fam](rng, a.cases, work):
                start = time.time()
                outcome, rc, tail = run(cli, args, work)
                c[outcome] = c.get(outcome, 0) + 1
                if outcome != "handled":
                    bad.append((fam, what, outcome, rc, round(time.time() - start, 1), args, tail))
                if keep and os.path.isfile(keep) and outcome == "handled":
                    os.remove(keep)
        finally:
            if not bad:
                shutil.rmtree(work, ignore_errors=True)
        print(fam, json.dumps(c), flush=True)
    for fam, what, outcome, rc, secs, args, tail in bad:
        print(f"{outcome}: {fam} ({what}), exit {rc}, {secs} s: voxray-cli {' '.join(args)}\n  {tail!r}")
    total = sum(sum(c.values()) for c in counts.values())
    print(f"{total} cases, {len(bad)} not handled")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
