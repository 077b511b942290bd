"""Density isosurfaces of a 3D run coloured by the streamwise velocity (thesis Appendix C, Figs C.1-C.3),
from the (K, nz, ny, nx) maps of a 3D fields.h5: the density (or --quantity) is smoothed over a few
cells (Gaussian, across the periodic and Lees-Edwards images), averaged over the last
--average-frames frames ending at --frame when asked, and cut at --level times its mean by VTK's
flying edges; each triangle is coloured by V_x (or --color-by, density-weighted in the smoothing and
the frame average) interpolated at its vertices and shaded by its orientation to a light.  Axes:
x the flow, y the gradient (drawn upwards), z the vorticity direction."""
import math

import numpy as np

from _common import fail, figure, open_h5, parser, resolve_frame, run, save, text
from _isosurface import isosurface, smooth

KIND = "fields"
UPRIGHT = [0, 2, 1]  # drawn axes (x, z, y): the gradient direction y points up, as in the configuration picture
LABELS = {"velocity_x": "V_x", "velocity_y": "V_y", "velocity_z": "V_z", "temperature": "T", "density": "ρ"}


def arguments():
    p = parser(KIND, __doc__)
    p.add_argument("--group", default="average")
    p.add_argument("--quantity", default="density", help="the field whose isosurface is drawn")
    p.add_argument("--color-by", default="velocity_x", help="the field that colours the surface")
    p.add_argument("--level", type=float, default=1.5, help="isosurface at this multiple of the field's mean")
    p.add_argument("--smooth", type=float, default=1.0, help="Gaussian smoothing, standard deviation in cells (0: none)")
    p.add_argument("--average-frames", type=int, default=1, help="average this many frames ending at --frame")
    p.add_argument("--view", type=float, nargs=2, default=[22.0, -58.0], metavar=("ELEVATION", "AZIMUTH"))
    p.add_argument("--size", type=int, nargs=2, default=[1000, 800], metavar=("WIDTH", "HEIGHT"), help="pixels")
    p.add_argument("--colormap", default="coolwarm")
    a = p.parse_args()
    if a.group not in ("average", "instant"):
        fail(KIND, f"--group {a.group} is not one of average, instant")
    if not (0.0 < a.level < 1e6):
        fail(KIND, f"--level {a.level} is outside (0, 1e6)")
    if not (0.0 <= a.smooth <= 16.0):
        fail(KIND, f"--smooth {a.smooth} is outside [0, 16] cells")
    if not all(64 <= s <= 8000 for s in a.size):
        fail(KIND, f"--size {a.size[0]} {a.size[1]}: each must be in [64, 8000] pixels")
    import matplotlib

    if a.colormap not in matplotlib.colormaps:
        fail(KIND, f"--colormap {a.colormap} is not a matplotlib colormap (e.g. coolwarm, viridis)")
    return a


def averaged_volumes(f, a, k):
    """The smoothed scalar and colour fields averaged over the chosen frames (the colour weighted by
    the density), the mean of the scalar, and the Lees–Edwards state of frame k."""
    group = f[a.group]
    first = k - a.average_frames + 1
    if a.average_frames < 1 or first < 0:
        fail(KIND, f"--average-frames {a.average_frames} is outside [1, {k + 1}] for frame {k}")
    lx, nx = float(f.attrs["length_x"]), int(f.attrs["nx"])
    relative = int(f.attrs.get("subtract_shear_profile", 0)) == 1
    lees_edwards = text(f.attrs.get("boundary", "periodic")) == "lees-edwards"

    def image_state(frame):
        if not lees_edwards or "frames/shear_offset" not in f:
            return 0.0, 0.0
        velocity = 0.0 if relative else float(f["frames/shear_velocity"][frame])
        return float(f["frames/shear_offset"][frame]) / (lx / nx), velocity

    scalar_sum = weight_sum = colored_sum = 0.0
    for frame in range(first, k + 1):
        offset, velocity = image_state(frame)
        density = np.asarray(group["density"][frame], dtype=np.float64)
        scalar = np.asarray(group[a.quantity][frame], dtype=np.float64)
        color = np.asarray(group[a.color_by][frame], dtype=np.float64)
        color_velocity = velocity if a.color_by == "velocity_x" else 0.0
        scalar_sum = scalar_sum + smooth(scalar, a.smooth, cells_offset=offset)
        weight = smooth(density, a.smooth, cells_offset=offset)
        weight_sum = weight_sum + weight
        colored_sum = colored_sum + weight * smooth(color, a.smooth, density, offset, color_velocity)
    scalar = scalar_sum / a.average_frames
    color = np.divide(colored_sum, weight_sum, out=np.zeros_like(weight_sum), where=weight_sum > 0)
    return scalar, color, image_state(k)


def shaded_colors(vertices, triangles, values, cmap, norm, light=(0.45, 0.35, 0.82)):
    """Face colours: the colour map at the mean of the vertex values, darkened by the angle between
    the face and the light (Lambert, two-sided)."""
    a, b, c = (vertices[triangles[:, j]] for j in range(3))
    normals = np.cross(b - a, c - a)
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
    lambert = np.abs(normals @ (np.asarray(light) / np.linalg.norm(light)))
    rgba = cmap(norm(values[triangles].mean(axis=1)))
    rgba[:, :3] *= (0.35 + 0.65 * lambert)[:, None]
    return rgba


def box_outline(ax, box):
    corners = [(x, y, z) for x in (0, box[0]) for y in (0, box[1]) for z in (0, box[2])]
    for i, p in enumerate(corners):
        for q in corners[i + 1:]:
            if sum(u != v for u, v in zip(p, q)) == 1:
                ax.plot(*zip(p, q), color="0.25", linewidth=0.7)


def main():
    a = arguments()
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    import matplotlib

    with open_h5(KIND, a.input) as f:
        if "frames" not in f or a.group not in f:
            fail(KIND, f"{a.input} is not a fields file (no /frames or /{a.group})")
        if int(f.attrs.get("dimension", 2)) != 3:
            fail(KIND, f"{a.input} holds 2D fields: the isosurface picture needs a 3D run")
        group = f[a.group]
        missing = [q for q in (a.quantity, a.color_by, "density") if q not in group]
        if missing:
            fail(KIND, f"{' '.join(missing)}: not in /{a.group} (available: {', '.join(sorted(group))})")
        k = resolve_frame(KIND, a.frame, len(f["frames/t"]))
        box = (float(f.attrs["length_x"]), float(f.attrs["length_y"]), float(f.attrs["length_z"]))
        scalar, color, (offset, velocity) = averaged_volumes(f, a, k)
        mean = float(scalar.mean())
        level = a.level * mean
        vertices, triangles, values = isosurface(scalar, color, box, level, offset,
                                                 velocity if a.color_by == "velocity_x" else 0.0)
        t, c = float(f["frames/t"][k]), float(f["frames/c"][k])
        frames = "" if a.average_frames == 1 else f", mean of {a.average_frames} frames"
        title = (f"N = {int(f.attrs['particles'])}, ẽ = {float(f.attrs['restitution']):g}, "
                 f"{text(f.attrs.get('boundary', 'periodic'))}; t = {t:.4g}, c = {c:.4g}{frames}\n"
                 f"{LABELS.get(a.quantity, a.quantity)} = {a.level:g} × mean ({level:.4g}), smoothed over {a.smooth:g} cells; "
                 f"{int(f.attrs['nx'])} × {int(f.attrs['ny'])} × {int(f.attrs['nz'])} cells")
    fig = figure(a.size[0] / a.dpi, a.size[1] / a.dpi)
    ax = fig.add_subplot(projection="3d")
    cmap = matplotlib.colormaps[a.colormap]
    if len(values):
        extreme = float(np.max(np.abs(values))) or 1.0
        low, high = (-extreme, extreme) if a.color_by.startswith("velocity") else (float(values.min()), float(values.max()))
    else:
        low, high = -1.0, 1.0
    norm = matplotlib.colors.Normalize(low, high)
    if len(triangles):
        faces = shaded_colors(vertices, triangles, values, cmap, norm)
        # Edges in the face colours hide the seams antialiasing leaves between triangles.
        surface = Poly3DCollection(vertices[:, UPRIGHT][triangles], facecolors=faces, edgecolors=faces, linewidths=0.2)
        ax.add_collection3d(surface)
    else:
        title += "\n(no surface at this level)"
    drawn_box = tuple(box[i] for i in UPRIGHT)
    box_outline(ax, drawn_box)
    ax.set_xlim(0, drawn_box[0])
    ax.set_ylim(0, drawn_box[1])
    ax.set_zlim(0, drawn_box[2])
    ax.set_box_aspect(drawn_box)
    ax.set_xlabel("x (flow)")
    ax.set_ylabel("z (vorticity)")
    ax.set_zlabel("y (gradient)")
    ax.view_init(elev=a.view[0], azim=a.view[1])
    colorbar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.6, pad=0.08)
    colorbar.set_label(LABELS.get(a.color_by, a.color_by))
    ax.set_title(title, fontsize=9)
    save(fig, a.out, a.dpi)


if __name__ == "__main__":
    run(main)
