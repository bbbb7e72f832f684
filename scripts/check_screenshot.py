#!/usr/bin/python3
"""Checks that an rviz screenshot of the collision2d demo shows the world.

    check_screenshot.py SCREENSHOT.png RVIZ_CONFIG [--state WORLD_STATE.yaml]

RVIZ_CONFIG is the rviz file the screenshot used (its top-down view centre
and scale, and its background colour, say where a world point lands on the
screen); WORLD_STATE.yaml is `rosservice call /collision2d/get_world` output
taken at the photographed frame. Without --state it only checks that rviz is
up and draws something body-coloured. With it, passes when

  * the render area (background-coloured pixels) is found,
  * inside every body that is on screen, most sample points have the body's
    colour class: grey for static bodies, saturated for the others,
  * points far from every body are (nearly all) not body-coloured.

Exits 1 with a line per failing body otherwise. Uses only the standard
library, PyYAML and ImageMagick's `convert` (to read the PNG).
"""

import argparse
import math
import subprocess
import sys

import yaml

# Body message constants (msg/ of the package).
DISK = 0
STATIC = 1

# Colour classes, on 0..255 channels. Rendered colours are shaded by rviz's
# light, so the classes are wide; they only need to tell the marker colours
# (grey 0.55 for static, saturated hues otherwise) from the background and the
# translucent grid lines.
BACKGROUND_TOLERANCE = 6      # per channel
GREY_MAX_SPREAD = 16          # max - min channel of a grey pixel
GREY_MIN_LIFT = 60            # a static body's grey is this much brighter than the background
SATURATED_MIN_SPREAD = 60     # max - min channel of a dynamic/kinematic body's pixel

# Sampling: points at this fraction of the way from the centroid to each
# vertex (polygons) or of the radius (disks), plus the centroid itself.
INNER_FRACTION = 0.5
DISK_SAMPLE_DIRECTIONS = 6
# A body passes when at least this share of its on-screen samples has its
# colour class (contact arrows and outlines may cover a few).
MIN_BODY_HIT_SHARE = 0.6
# Empty-space probe grid (m) and clearance from every body (m).
EMPTY_GRID_STEP = 1.0
EMPTY_CLEARANCE = 0.6
MAX_EMPTY_COLOURED_SHARE = 0.02
# Rows and columns scanned for the render area (px apart).
RENDER_SCAN_STEP = 8
# The render area must cover at least this share of the screenshot.
MIN_RENDER_AREA_SHARE = 0.3
# Without a world state: share of the render area that must be body-coloured
# for rviz to count as drawing the world (the demo's ground alone is ~4%).
MIN_DRAWN_SHARE = 0.01
# Failing bodies listed in full before the summary.
MAX_REPORTED_LINES = 12
# A screenshot must show at least this many bodies to count as a check.
MIN_BODIES_ON_SCREEN = 3


class Image:
    """8-bit RGB pixels read through ImageMagick as binary PPM."""

    def __init__(self, path):
        ppm = subprocess.run(["convert", path, "-depth", "8", "ppm:-"], check=True,
                             stdout=subprocess.PIPE).stdout
        fields, offset = [], 0
        while len(fields) < 4:  # magic, width, height, maxval
            while ppm[offset:offset + 1].isspace():
                offset += 1
            if ppm[offset:offset + 1] == b"#":
                offset = ppm.index(b"\n", offset) + 1
                continue
            end = offset
            while not ppm[end:end + 1].isspace():
                end += 1
            fields.append(ppm[offset:end])
            offset = end
        if fields[0] != b"P6" or int(fields[3]) != 255:
            raise ValueError("unexpected PPM from convert: %r" % fields)
        self.width, self.height = int(fields[1]), int(fields[2])
        self.data = ppm[offset + 1:]

    def pixel(self, x, y):
        i = 3 * (y * self.width + x)
        return tuple(self.data[i:i + 3])


class View:
    """World (m) to screen (px) for rviz's TopDownOrtho view: the view centre
    (X, Y) sits at the centre of the render area, Scale pixels per metre."""

    def __init__(self, config, area):
        current = config["Visualization Manager"]["Views"]["Current"]
        if current["Class"] != "rviz/TopDownOrtho" or float(current.get("Angle", 0)) != 0.0:
            raise ValueError("the rviz view must be an unrotated TopDownOrtho")
        self.x, self.y = float(current["X"]), float(current["Y"])
        self.scale = float(current["Scale"])
        self.area = area  # (left, top, right, bottom), inclusive

    def to_screen(self, x, y):
        left, top, right, bottom = self.area
        cx, cy = 0.5 * (left + right + 1), 0.5 * (top + bottom + 1)
        return (int(math.floor(cx + (x - self.x) * self.scale)),
                int(math.floor(cy - (y - self.y) * self.scale)))

    def visible(self, px, py):
        left, top, right, bottom = self.area
        return left <= px <= right and top <= py <= bottom


def spread(rgb):
    return max(rgb) - min(rgb)


def is_background(rgb, background):
    return all(abs(a - b) <= BACKGROUND_TOLERANCE for a, b in zip(rgb, background))


def is_static_grey(rgb, background):
    return spread(rgb) <= GREY_MAX_SPREAD and sum(rgb) / 3.0 >= sum(background) / 3.0 + GREY_MIN_LIFT


def is_saturated(rgb):
    return spread(rgb) >= SATURATED_MIN_SPREAD


def body_coloured(rgb, background):
    return is_static_grey(rgb, background) or is_saturated(rgb)


def render_area(image, background):
    """Bounding box of the background-coloured pixels (rviz's 3D view), from
    every RENDER_SCAN_STEP-th row and column."""
    xs, ys = [], []
    for y in range(0, image.height, RENDER_SCAN_STEP):
        row = [x for x in range(image.width) if is_background(image.pixel(x, y), background)]
        if row:
            xs += [row[0], row[-1]]
    for x in range(0, image.width, RENDER_SCAN_STEP):
        column = [y for y in range(image.height) if is_background(image.pixel(x, y), background)]
        if column:
            ys += [column[0], column[-1]]
    if not xs or not ys:
        return None
    left, top, right, bottom = min(xs), min(ys), max(xs), max(ys)
    if (right - left + 1) * (bottom - top + 1) < MIN_RENDER_AREA_SHARE * image.width * image.height:
        return None
    return left, top, right, bottom


def rotate(x, y, theta):
    c, s = math.cos(theta), math.sin(theta)
    return c * x - s * y, s * x + c * y


def sample_points(body):
    """World points well inside the body."""
    px, py, theta = body["pose"]["x"], body["pose"]["y"], body["pose"]["theta"]
    points = [(px, py)]
    if body["shape"] == DISK:
        r = INNER_FRACTION * body["radius"]
        for k in range(DISK_SAMPLE_DIRECTIONS):
            # Offset by half a step so no sample lies on the radius line at theta.
            a = theta + 2.0 * math.pi * (k + 0.5) / DISK_SAMPLE_DIRECTIONS
            points.append((px + r * math.cos(a), py + r * math.sin(a)))
        return points
    for vertex in body["vertices"]:
        vx, vy = rotate(vertex["x"], vertex["y"], theta)
        points.append((px + INNER_FRACTION * vx, py + INNER_FRACTION * vy))
    return points


def outline(body):
    """World vertices of a polygon body, counter-clockwise."""
    px, py, theta = body["pose"]["x"], body["pose"]["y"], body["pose"]["theta"]
    return [(px + x, py + y) for x, y in (rotate(v["x"], v["y"], theta) for v in body["vertices"])]


def distance_to_segment(p, a, b):
    ax, ay = b[0] - a[0], b[1] - a[1]
    t = ((p[0] - a[0]) * ax + (p[1] - a[1]) * ay) / (ax * ax + ay * ay)
    t = min(1.0, max(0.0, t))
    return math.hypot(p[0] - a[0] - t * ax, p[1] - a[1] - t * ay)


def distance_to_body(p, body):
    """0 inside the body, else the distance to its boundary (m)."""
    if body["shape"] == DISK:
        return max(0.0, math.hypot(p[0] - body["pose"]["x"], p[1] - body["pose"]["y"]) - body["radius"])
    corners = outline(body)
    edges = list(zip(corners, corners[1:] + corners[:1]))
    inside = all((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0.0 for a, b in edges)
    return 0.0 if inside else min(distance_to_segment(p, a, b) for a, b in edges)


def check_body(image, view, body, background):
    """(on-screen samples, samples of the right colour class)."""
    wanted = ((lambda rgb: is_static_grey(rgb, background)) if body["type"] == STATIC else is_saturated)
    shown, hits = 0, 0
    for x, y in sample_points(body):
        sx, sy = view.to_screen(x, y)
        if view.visible(sx, sy):
            shown += 1
            hits += 1 if wanted(image.pixel(sx, sy)) else 0
    return shown, hits


def empty_points(view, bodies):
    """Grid points of the visible world that are clear of every body."""
    left, top, right, bottom = view.area
    x0 = view.x - (0.5 * (right - left)) / view.scale
    x1 = view.x + (0.5 * (right - left)) / view.scale
    y0 = view.y - (0.5 * (bottom - top)) / view.scale
    y1 = view.y + (0.5 * (bottom - top)) / view.scale
    y = math.ceil(y0) + 0.5 * EMPTY_GRID_STEP
    while y < y1:
        x = math.ceil(x0) + 0.5 * EMPTY_GRID_STEP
        while x < x1:
            if all(distance_to_body((x, y), b) > EMPTY_CLEARANCE for b in bodies):
                yield x, y
            x += EMPTY_GRID_STEP
        y += EMPTY_GRID_STEP


def background_color(config):
    text = config["Visualization Manager"]["Global Options"]["Background Color"]
    return tuple(int(c) for c in text.split(";"))


def check(image, state, config):
    """Returns (passed, lines about failing bodies, summary lines)."""
    background = background_color(config)
    area = render_area(image, background)
    if area is None:
        return False, [], ["no rviz render area (background %s) in the screenshot: rviz is not up" % (background,)]
    view = View(config, area)
    body_lines, summary, failed, drawn, on_screen = [], [], 0, 0, 0
    for body in state["bodies"]:
        shown, hits = check_body(image, view, body, background)
        if shown == 0:
            continue
        on_screen += 1
        if hits >= MIN_BODY_HIT_SHARE * shown:
            drawn += 1
        else:
            failed += 1
            body_lines.append("body %d (%s) at (%.2f, %.2f): %d of %d sample pixels have its colour" % (
                body["id"], "static" if body["type"] == STATIC else "moving",
                body["pose"]["x"], body["pose"]["y"], hits, shown))
    empty = [view.to_screen(x, y) for x, y in empty_points(view, state["bodies"])]
    coloured = sum(1 for sx, sy in empty if view.visible(sx, sy) and body_coloured(image.pixel(sx, sy), background))
    empty_share = coloured / float(len(empty)) if empty else 1.0
    summary.append("render area %s; %d of %d bodies on screen drawn in their colours; "
                 "%d of %d empty points body-coloured" % (area, drawn, on_screen, coloured, len(empty)))
    passed = (failed == 0 and on_screen >= MIN_BODIES_ON_SCREEN and empty_share <= MAX_EMPTY_COLOURED_SHARE)
    if on_screen < MIN_BODIES_ON_SCREEN:
        summary.append("too few bodies on screen (%d) for a meaningful check" % on_screen)
    if empty_share > MAX_EMPTY_COLOURED_SHARE:
        summary.append("body colours where there is no body: the view does not match the world")
    return passed, body_lines, summary


def check_drawn(image, config):
    """Returns (passed, [], summary): rviz is up and draws body colours."""
    background = background_color(config)
    area = render_area(image, background)
    if area is None:
        return False, [], ["no rviz render area (background %s) in the screenshot: rviz is not up" % (background,)]
    left, top, right, bottom = area
    probes = [(x, y) for y in range(top, bottom + 1, RENDER_SCAN_STEP)
              for x in range(left, right + 1, RENDER_SCAN_STEP)]
    coloured = sum(1 for x, y in probes if body_coloured(image.pixel(x, y), background))
    share = coloured / float(len(probes))
    return share >= MIN_DRAWN_SHARE, [], ["render area %s; %.1f%% of it body-coloured" % (area, 100.0 * share)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("screenshot")
    parser.add_argument("rviz_config")
    parser.add_argument("--state", help="get_world output at the photographed frame")
    args = parser.parse_args()
    with open(args.rviz_config) as f:
        config = yaml.safe_load(f)
    if args.state:
        with open(args.state) as f:
            response = yaml.safe_load(f)
        state = response["state"] if "state" in response else response
        passed, body_lines, summary = check(Image(args.screenshot), state, config)
    else:
        passed, body_lines, summary = check_drawn(Image(args.screenshot), config)
    if len(body_lines) > MAX_REPORTED_LINES:
        hidden = len(body_lines) - MAX_REPORTED_LINES
        body_lines = body_lines[:MAX_REPORTED_LINES] + ["... and %d more bodies" % hidden]
    for line in body_lines + summary:
        print(("" if passed else "FAIL: ") + line)
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
