"""A 3D configuration from snapshots.h5 (thesis Appendix C): every sphere drawn to scale as a shaded
disk (a sphere impostor: per-pixel depth and normal, so spheres occlude each other exactly, as a
depth buffer sorts them), in an orthographic or perspective view, coloured by the streamwise velocity
v_x (default under Lees-Edwards) or the speed |v| (default otherwise).  y (gradient) is drawn
upwards, x (flow) and z (vorticity) span the floor; the box edges are drawn where no sphere hides
them.  Fixed obstacles (dataset obstacles) are drawn as grey spheres among them.  A few 10^4
spheres draw in seconds."""
import math

import numpy as np

from _common import fail, figure, open_h5, parser, require_format, resolve_frame, run, save, text

KIND = "config"
CHUNK = 8192  # spheres rasterised at once (memory: CHUNK × stencil fragments)


def arguments():
    p = parser(KIND, __doc__)
    p.add_argument("--color", default="auto", help="auto, velocity_x, speed or none")
    p.add_argument("--view", type=float, nargs=2, default=[22.0, -58.0], metavar=("ELEVATION", "AZIMUTH"))
    p.add_argument("--perspective", action="store_true", help="perspective instead of orthographic projection")
    p.add_argument("--width", type=int, default=1000, help="pixels; the height is 3/4 of it")
    p.add_argument("--no-legend", action="store_true")
    a = p.parse_args()
    if a.color not in ("auto", "velocity_x", "speed", "none"):
        fail(KIND, f"--color {a.color} is not one of auto, velocity_x, speed, none (3D runs)")
    if not 64 <= a.width <= 8000:
        fail(KIND, f"--width {a.width} is outside [64, 8000] for a 3D picture")
    return a


def camera(elevation, azimuth):
    """Right, up and toward-the-viewer unit vectors in the picture's world (X, Y, Z) = (x, z, y):
    azimuth turns about the vertical y axis, elevation tilts the view down onto the floor."""
    e, a = math.radians(elevation), math.radians(azimuth)
    toward = np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])
    right = np.array([-math.sin(a), math.cos(a), 0.0])
    return right, np.cross(toward, right), toward


class Projection:
    """Lab points (x, y, z) → pixel column, row (row 0 at the top), depth toward the viewer (world
    units) and the pixels per world length at that point, fitted so the whole box fills the frame."""

    def __init__(self, box, view, perspective, width, height, margin=0.06):
        self.right, self.up, self.toward = camera(*view)
        self.centre = 0.5 * np.array(box)
        self.distance = 2.5 * float(np.linalg.norm(box)) if perspective else math.inf
        corners = np.array([(x, y, z) for x in (0, box[0]) for y in (0, box[1]) for z in (0, box[2])], dtype=float)
        u, v, _, s = self._plane(corners)
        su, sv = u * s, v * s
        span = max((su.max() - su.min()) / (width * (1 - 2 * margin)), (sv.max() - sv.min()) / (height * (1 - 2 * margin)))
        self.scale = 1.0 / span
        self.offset = (0.5 * width - 0.5 * (su.max() + su.min()) * self.scale, 0.5 * height + 0.5 * (sv.max() + sv.min()) * self.scale)

    def _plane(self, points):
        world = (np.asarray(points) - self.centre)[:, [0, 2, 1]]
        depth = world @ self.toward
        shrink = np.ones_like(depth) if math.isinf(self.distance) else self.distance / (self.distance - depth)
        return world @ self.right, world @ self.up, depth, shrink

    def __call__(self, points):
        u, v, depth, shrink = self._plane(points)
        pixels_per_length = self.scale * shrink
        return self.offset[0] + u * pixels_per_length, self.offset[1] - v * pixels_per_length, depth, pixels_per_length


def rasterise(columns, rows, depth, radius_px, radius, width, height):
    """Nearest sphere surface per pixel: (particle index or −1, its depth, offsets dx, dy from the
    centre in pixels), by depth test of every covered pixel of every sphere."""
    best_depth = np.full(width * height, -np.inf)
    best = np.full(width * height, -1, dtype=np.int64)
    offset_x = np.zeros(width * height)
    offset_y = np.zeros(width * height)
    order = np.argsort(radius_px)
    for start in range(0, len(order), CHUNK):
        chunk = order[start:start + CHUNK]
        reach = int(math.ceil(radius_px[chunk].max()))
        grid = np.arange(-reach, reach + 1)
        dx, dy = (g.ravel() for g in np.meshgrid(grid, grid))
        col = np.floor(columns[chunk])[:, None] + dx[None, :]
        row = np.floor(rows[chunk])[:, None] + dy[None, :]
        ex = col + 0.5 - columns[chunk][:, None]  # pixel centre relative to the sphere centre
        ey = row + 0.5 - rows[chunk][:, None]
        inside2 = radius_px[chunk][:, None] ** 2 - ex * ex - ey * ey
        keep = (inside2 > 0) & (col >= 0) & (col < width) & (row >= 0) & (row < height)
        pixel = (row * width + col)[keep].astype(np.int64)
        scale = radius_px[chunk][:, None] / radius[chunk][:, None]
        surface = (depth[chunk][:, None] + np.sqrt(np.where(keep, inside2, 0.0)) / scale)[keep]
        owner = np.broadcast_to(chunk[:, None], keep.shape)[keep]
        nearest = np.lexsort((-surface, pixel))
        first = np.ones(len(nearest), dtype=bool)
        first[1:] = pixel[nearest][1:] != pixel[nearest][:-1]
        winners = nearest[first]
        won = surface[winners] > best_depth[pixel[winners]]
        target = pixel[winners][won]
        best_depth[target] = surface[winners][won]
        best[target] = owner[winners][won]
        offset_x[target] = ex[keep][winners][won]
        offset_y[target] = ey[keep][winners][won]
    return best, best_depth, offset_x, offset_y


def shade(base, best, offset_x, offset_y, radius_px, light=(-0.45, 0.55, 0.70)):
    """Lambert plus a white highlight on each sphere's normal (dx, −dy, dz) / r; white background."""
    image = np.ones((len(best), 3))
    hit = best >= 0
    r = radius_px[best[hit]]
    nx, ny = offset_x[hit] / r, -offset_y[hit] / r
    nz = np.sqrt(np.clip(1.0 - nx * nx - ny * ny, 0.0, 1.0))
    l = np.asarray(light) / np.linalg.norm(light)
    diffuse = np.clip(nx * l[0] + ny * l[1] + nz * l[2], 0.0, 1.0)
    half = (l + np.array([0.0, 0.0, 1.0])) / np.linalg.norm(l + np.array([0.0, 0.0, 1.0]))
    specular = np.clip(nx * half[0] + ny * half[1] + nz * half[2], 0.0, 1.0) ** 24
    image[hit] = base[best[hit]] * (0.3 + 0.7 * diffuse)[:, None] + 0.35 * specular[:, None]
    return np.clip(image, 0.0, 1.0)


def draw_box(ax, project, box, best_depth, width, height):
    """The 12 box edges, hidden where a sphere is in front of them."""
    corners = [(x, y, z) for x in (0, box[0]) for y in (0, box[1]) for z in (0, box[2])]
    t = np.linspace(0.0, 1.0, 400)[:, None]
    for i, p in enumerate(corners):
        for q in corners[i + 1:]:
            if sum(u != v for u, v in zip(p, q)) != 1:
                continue
            points = np.asarray(p) + t * (np.asarray(q) - np.asarray(p))
            col, row, depth, _ = project(points)
            inside = (col >= 0) & (col < width) & (row >= 0) & (row < height)
            pixel = np.clip(row.astype(int), 0, height - 1) * width + np.clip(col.astype(int), 0, width - 1)
            visible = inside & (depth >= best_depth[pixel] - 1e-9)
            ax.plot(np.where(visible, col, np.nan), np.where(visible, row, np.nan), color="0.2", linewidth=0.8)


def draw_axes_key(ax, project, box, width, height):
    """Arrows for x (flow), y (gradient), z (vorticity) from the lower-left corner of the picture."""
    origin = np.zeros(3)
    base_col, base_row, _, _ = project(origin[None, :])
    for axis, name in enumerate(("x (flow)", "y (gradient)", "z (vorticity)")):
        tip = np.zeros(3)
        tip[axis] = 0.18 * min(box)
        col, row, _, _ = project(tip[None, :])
        direction = np.array([col[0] - base_col[0], row[0] - base_row[0]])
        direction *= 0.09 * width / max(np.linalg.norm(direction), 1e-12)
        start = np.array([0.06 * width, 0.93 * height])
        ax.annotate("", xy=start + direction, xytext=start, arrowprops=dict(arrowstyle="->", color="black", lw=1.0))
        ax.text(*(start + 1.25 * direction), name, fontsize=7, ha="center", va="center")


def main():
    a = arguments()
    import matplotlib

    with open_h5(KIND, a.input) as f:
        require_format(KIND, f, a.input, "granule-snapshots", "granule run")
        if int(f.attrs.get("dimension", 2)) != 3:
            fail(KIND, f"{a.input} holds a 2D run: use the 2D picture")
        frames = min(len(f["positions"]), len(f["velocities"]), len(f["time"]))
        k = resolve_frame(KIND, a.frame, frames)
        positions = np.asarray(f["positions"][k], dtype=np.float64)
        velocities = np.asarray(f["velocities"][k], dtype=np.float64)
        box = tuple(float(b) for b in f.attrs["box"])
        diameters = np.asarray(f["diameters"], dtype=np.float64) if "diameters" in f else np.full(len(positions), float(f.attrs["diameter"]))
        boundary = text(f.attrs.get("boundary", "periodic"))
        obstacles = np.asarray(f["obstacles"][()], dtype=np.float64).reshape(-1, 6) if "obstacles" in f else np.zeros((0, 6))
        title = (f"N = {len(positions)}, ẽ = {float(f.attrs['restitution']):g}, {boundary}; "
                 f"t = {float(f['time'][k]):.4g}, c = {float(f['collisions_per_particle'][k]):.4g}")
    coloring = a.color if a.color != "auto" else ("velocity_x" if boundary == "lees-edwards" else "speed")
    width, height = a.width, int(round(0.75 * a.width))
    legend = coloring != "none" and not a.no_legend
    picture_width = int(round(width * (0.86 if legend else 1.0)))
    picture_height = int(round(height * 0.93))
    project = Projection(box, a.view, a.perspective, picture_width, picture_height)
    columns, rows, depth, pixels_per_length = project(np.concatenate([positions, obstacles[:, :3]]))
    radius = 0.5 * np.concatenate([diameters, obstacles[:, 3]])
    radius_px = np.maximum(radius * pixels_per_length, 0.5)
    if coloring == "velocity_x":
        values = velocities[:, 0]
        extreme = float(np.max(np.abs(values))) or 1.0
        norm, cmap, label = matplotlib.colors.Normalize(-extreme, extreme), matplotlib.colormaps["coolwarm"], "v_x"
    elif coloring == "speed":
        values = np.linalg.norm(velocities, axis=1)
        norm, cmap, label = matplotlib.colors.Normalize(0.0, float(values.max()) or 1.0), matplotlib.colormaps["viridis"], "|v|"
    else:
        values, norm, cmap, label = np.zeros(len(positions)), matplotlib.colors.Normalize(-1, 1), matplotlib.colormaps["gray"], ""
    base = cmap(norm(values))[:, :3] if coloring != "none" else np.full((len(positions), 3), 0.6)
    base = np.concatenate([base, np.full((len(obstacles), 3), 0.45)])
    best, best_depth, offset_x, offset_y = rasterise(columns, rows, depth, radius_px, radius, picture_width, picture_height)
    image = shade(base, best, offset_x, offset_y, radius_px).reshape(picture_height, picture_width, 3)

    fig = figure(width / a.dpi, height / a.dpi)
    fig.set_layout_engine(None)
    ax = fig.add_axes([0.0, 0.0, picture_width / width, picture_height / height])
    ax.imshow(image, interpolation="nearest", extent=(0, picture_width, picture_height, 0))
    draw_box(ax, project, box, best_depth, picture_width, picture_height)
    draw_axes_key(ax, project, box, picture_width, picture_height)
    ax.set_xlim(0, picture_width)
    ax.set_ylim(picture_height, 0)
    ax.set_axis_off()
    fig.text(0.5, 0.985, title, ha="center", va="top", fontsize=9)
    if legend:
        bar = fig.add_axes([0.89, 0.15, 0.025, 0.65])
        fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), cax=bar).set_label(label)
    save(fig, a.out, a.dpi)


if __name__ == "__main__":
    run(main)
