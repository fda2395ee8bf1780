"""The viewer draws the bodies where the recording puts them (ctest
viewer_screenshot, label program).

Records the ragdoll (two worlds side by side), screenshots the viewer in
headless Chromium at two times, and checks that at each body's centre of
mass, as the page projects it from the recording, the screenshot shows a
body: not the background, a saturated colour (not the grey grid or the
white joint lines), mostly the body's own hue; and that the bodies moved on
screen between the two times. The ragdoll has no collision shapes: its
bodies are drawn from their mass properties.

Then box-stack, a contact scene (two worlds side by side): the page draws
its collision shapes, one ground plane (shared by the two worlds) and ten
boxes, with the same pixel checks at the boxes and the ground plane under
the whole bottom edge of the view; and the same recording without its
body_shape_* arrays (as written before shapes were recorded) falls back to
the mass-based look: no plane, boxes guessed from the inertia, the ground a
marker.

usage: viewer_screenshot_test.py MANYWORLDS VIEWER_DIR WORK_DIR
Exit 77 (ctest: skipped) without Chromium."""

import colorsys
import pathlib
import sys
import zipfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import headless_viewer  # noqa: E402

TIMES = (0.0, 1.5)  # s
SIZE = (480, 320)


def hex_rgb(text):
    return tuple(int(text[i:i + 2], 16) for i in (1, 3, 5))


def hue(rgb):
    return colorsys.rgb_to_hsv(*(c / 255 for c in rgb))[0]


def check_frame(state, png):
    width, height, rows = headless_viewer.decode_png(png)
    assert (width, height) == SIZE, f"screenshot {width}x{height}"
    background = hex_rgb(state["background"])
    corner = rows[2][2]
    assert max(abs(a - b) for a, b in zip(corner, background)) <= 8, \
        f"corner pixel {corner} is not the background {background}"
    own_hue = 0
    bodies = [b for b in state["bodies"] if not b["static"]]
    for body in bodies:
        x, y = round(body["x"]), round(body["y"])
        assert 0 <= x < width and 0 <= y < height, f"{body['name']} off screen at ({x}, {y})"
        pixel = rows[y][x]
        distance = max(abs(a - b) for a, b in zip(pixel, background))
        chroma = max(pixel) - min(pixel)
        print(f"  world {body['world']} {body['name']:16s} at ({x:3d}, {y:3d}): pixel {pixel}, "
              f"colour {body['color']}")
        assert distance > 40 and chroma > 30, \
            f"world {body['world']} {body['name']}: pixel {pixel} at ({x}, {y}) is not a body"
        difference = abs(hue(pixel) - hue(hex_rgb(body["color"])))
        own_hue += min(difference, 1 - difference) < 0.06
    # A body may hide another's centre of mass; most show their own colour.
    assert own_hue >= 0.7 * len(bodies), f"only {own_hue} of {len(bodies)} bodies in their colour"
    return rows


def strip_shapes(recording, old):
    """`recording` without its body_shape_* members: a file of the same format
    as written before the shapes were recorded."""
    with zipfile.ZipFile(recording) as source, zipfile.ZipFile(old, "w") as target:
        for info in source.infolist():
            if not info.filename.startswith("body_shape_"):
                target.writestr(info, source.read(info))


def check_contact_scene(manyworlds, chromium, viewer_dir, work):
    recording = work / "box-stack.npz"
    headless_viewer.record(manyworlds, "box-stack", recording, worlds="0,1", steps=90)
    png = work / "box-stack.png"
    state = headless_viewer.screenshot(chromium, viewer_dir, recording, 1.0, png, SIZE)
    print(f"box-stack at {state['frameTime']:.4f} s: drawn {state['shapes']}")
    assert state["recordedShapes"], "the recording holds no shapes"
    assert state["shapes"] == {"plane": 1, "box": 10}, \
        f"box-stack drawn as {state['shapes']}, not one ground plane and 10 boxes"
    for body in state["bodies"]:
        expected = "plane" if body["name"] == "ground" else "box"
        assert body["shape"] == body["look"] == expected, \
            f"world {body['world']} {body['name']}: shape {body['shape']}, drawn as {body['look']}"
    rows = check_frame(state, png)
    # The plane: under the stacks, the view's whole bottom edge is ground.
    background = hex_rgb(state["background"])
    bottom = rows[SIZE[1] - 2]
    ground = sum(max(abs(a - b) for a, b in zip(pixel, background)) > 8 for pixel in bottom)
    print(f"  bottom edge: {ground} of {SIZE[0]} pixels are not the background")
    assert ground >= 0.95 * SIZE[0], "no ground plane along the bottom of the view"

    old = work / "box-stack-old.npz"
    old.unlink(missing_ok=True)
    strip_shapes(recording, old)
    state = headless_viewer.screenshot(chromium, viewer_dir, old, 1.0, work / "box-stack-old.png",
                                       SIZE)
    print(f"box-stack without shapes: drawn {state['shapes']}")
    assert not state["recordedShapes"]
    assert "plane" not in state["shapes"]
    for body in state["bodies"]:
        expected = "marker" if body["name"] == "ground" else "box"
        assert body["shape"] == "none" and body["look"] == expected, \
            f"{body['name']} of an old recording: shape {body['shape']}, drawn as {body['look']}"


def main():
    manyworlds, viewer_dir, work = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
    chromium = headless_viewer.find_chromium()
    if chromium is None:
        print("chromium not found (scripts/install-deps --test installs it): skipped")
        return 77
    work.mkdir(parents=True, exist_ok=True)
    recording = work / "ragdoll.npz"
    headless_viewer.record(manyworlds, "ragdoll", recording, worlds="0,1", steps=120)
    states, images = [], []
    for time in TIMES:
        png = work / f"ragdoll-{time:g}.png"
        state = headless_viewer.screenshot(chromium, viewer_dir, recording, time, png, SIZE)
        print(f"t = {time} s: frame {state['frame']} ({state['frameTime']:.4f} s), "
              f"{len(state['bodies'])} bodies, screenshot {png}")
        images.append(check_frame(state, png))
        states.append(state)
        # No collision shapes: every body drawn from its mass properties.
        assert all(b["shape"] == "none" and b["look"] != "plane" for b in state["bodies"])
    moved = max(abs(a["x"] - b["x"]) + abs(a["y"] - b["y"])
                for a, b in zip(states[0]["bodies"], states[1]["bodies"]))
    changed = sum(p != q for r0, r1 in zip(*images) for p, q in zip(r0, r1))
    print(f"largest on-screen move of a body between {TIMES[0]} s and {TIMES[1]} s: "
          f"{moved:.1f} px; {changed} pixels changed")
    assert moved > 3, "no body moved on screen"
    assert changed > 200, "the two screenshots are (nearly) the same"
    check_contact_scene(manyworlds, chromium, viewer_dir, work)
    print("viewer_screenshot: passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
