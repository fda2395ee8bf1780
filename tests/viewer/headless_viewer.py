"""Driving the recording viewer (viewer/, docs/viewer.md) in headless Chromium:
record a scene with the manyworlds program, load the page with
?recording=...&time=..., take a screenshot and read what the page published
(each body's projected centre of mass and colour). Shared by the screenshot
test and scripts/scene-pictures. Every command is an argument vector: no
shell ever reads a path or a scene id."""

import html
import json
import pathlib
import re
import shutil
import struct
import subprocess
import urllib.parse
import zlib

# Headless Chromium as root needs --no-sandbox; WebGL without a GPU needs
# SwiftShader through ANGLE (Chromium 156 refuses it without
# --enable-unsafe-swiftshader); file:// pages may read the recording with
# --allow-file-access-from-files. The virtual time budget lets the page load
# and draw before the screenshot is taken.
CHROMIUM_FLAGS = [
    "--headless", "--no-sandbox", "--disable-gpu-sandbox", "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader", "--allow-file-access-from-files",
    "--force-device-scale-factor=1", "--hide-scrollbars", "--virtual-time-budget=5000",
]


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def record(manyworlds, scene, path, worlds="0", steps=120):
    """Runs `scene` for `steps` steps (no warm-up) and records `worlds`."""
    path = pathlib.Path(path)
    path.unlink(missing_ok=True)
    subprocess.run([str(manyworlds), "run", "--scene", scene, "--worlds", "4", "--threads", "1",
                    "--steps", str(steps), "--warmup", "0", "--record", str(path),
                    "--record-worlds", worlds],
                   check=True, stdout=subprocess.DEVNULL)


def screenshot(chromium, viewer_dir, recording, time, png, size=(480, 320), layout="side"):
    """The viewer's bare 3D view of `recording` at `time` s saved as `png`;
    returns the state the page published (JSON of #viewer-state)."""
    query = urllib.parse.urlencode({
        "bare": "1", "recording": pathlib.Path(recording).resolve().as_uri(),
        "time": repr(float(time)), "layout": layout, "size": f"{size[0]}x{size[1]}"})
    url = (pathlib.Path(viewer_dir).resolve() / "index.html").as_uri() + "?" + query
    result = subprocess.run(
        [chromium, *CHROMIUM_FLAGS, f"--window-size={size[0]},{size[1]}",
         f"--screenshot={pathlib.Path(png).resolve()}", "--dump-dom", url],
        check=True, capture_output=True, text=True, timeout=120)
    found = re.search(r'<pre id="viewer-state">(.*?)</pre>', result.stdout, re.S)
    if not found or not found.group(1).strip():
        status = re.search(r'<div id="status"[^>]*>(.*?)</div>', result.stdout, re.S)
        raise RuntimeError("the viewer published nothing; its status line: " +
                           (html.unescape(status.group(1)) if status else "(none)"))
    return json.loads(html.unescape(found.group(1)))


def decode_png(path):
    """(width, height, rows) of an 8-bit RGB or RGBA PNG: rows[y][x] = (r, g, b)."""
    data = pathlib.Path(path).read_bytes()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        chunk = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        at += 12 + length
    width, height, depth, color, _, _, interlace = header
    if depth != 8 or color not in (2, 6) or interlace != 0:
        raise ValueError(f"{path}: only 8-bit RGB/RGBA, non-interlaced PNGs are read")
    channels = 3 if color == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        kind, row = line[0], bytearray(line[1:])
        for i in range(stride):  # the five PNG filters
            left = row[i - channels] if i >= channels else 0
            up = previous[i]
            corner = previous[i - channels] if i >= channels else 0
            if kind == 1:
                row[i] = (row[i] + left) & 0xFF
            elif kind == 2:
                row[i] = (row[i] + up) & 0xFF
            elif kind == 3:
                row[i] = (row[i] + (left + up) // 2) & 0xFF
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                predictor = left if pa <= pb and pa <= pc else up if pb <= pc else corner
                row[i] = (row[i] + predictor) & 0xFF
        rows.append([tuple(row[x * channels:x * channels + 3]) for x in range(width)])
        previous = row
    return width, height, rows
