"""Cell fields of a 3D box as volumes: Lees–Edwards-aware padding and smoothing, and the isosurface
of one field coloured by another (VTK's flying edges from Debian's python3-vtk9).

Arrays are indexed [iz, iy, ix] (x fastest in memory, as the (K, nz, ny, nx) maps of fields.h5), one
value per cell, at the cell centres ((ix + ½) Δx, (iy + ½) Δy, (iz + ½) Δz).  x and z are plainly
periodic; across y the images above (below) the box are the box shifted by +Δ (−Δ) along x and
moving at +U (−U) along x (thesis §1.4.2), so a field read across the top is the bottom rows
shifted by Δ, plus U for the streamwise velocity of the lab frame.
"""
import math

import numpy as np


def _shifted_rows(rows, cells_shift):
    """rows[..., ix] evaluated at ix − cells_shift (periodic linear interpolation along x)."""
    left = math.floor(cells_shift)
    w = cells_shift - left
    return (1.0 - w) * np.roll(rows, left, axis=-1) + w * np.roll(rows, left + 1, axis=-1)


def pad(field, layers, cells_offset=0.0, image_velocity=0.0):
    """`field` [nz, ny, nx] with `layers` cells of its periodic images on every side: plain in x and
    z, Lees–Edwards in y (image offset `cells_offset` = Δ/Δx cells, image velocity added as
    ±`image_velocity`: U for V_x in the lab frame, 0 for other fields)."""
    nz, ny, nx = field.shape
    if layers > ny:
        raise ValueError(f"cannot pad {layers} rows on a grid of {ny} rows")
    above = _shifted_rows(field[:, :layers, :], cells_offset) + image_velocity
    below = _shifted_rows(field[:, ny - layers:, :], -cells_offset) - image_velocity
    grown = np.concatenate([below, field, above], axis=1)
    return np.pad(grown, ((layers, layers), (0, 0), (layers, layers)), mode="wrap")


def _gaussian(padded, cells, layers):
    from scipy.ndimage import gaussian_filter

    wide = gaussian_filter(padded, sigma=cells, mode="wrap", truncate=4.0)
    return wide[layers:-layers, layers:-layers, layers:-layers]


def smooth(field, cells, weight=None, cells_offset=0.0, image_velocity=0.0):
    """Gaussian smoothing with a standard deviation of `cells` cells along each axis, across the
    periodic and Lees–Edwards images (0: the field itself).  With a `weight` (the density), the
    weighted mean smooth(weight · field) / smooth(weight), as a velocity is averaged by mass
    (0 where there is no weight)."""
    if cells <= 0:
        return field
    layers = min(int(math.ceil(4.0 * cells)), field.shape[1])
    padded = pad(field, layers, cells_offset, image_velocity)
    if weight is None:
        return _gaussian(padded, cells, layers)
    padded_weight = pad(weight, layers, cells_offset)
    total = _gaussian(padded_weight, cells, layers)
    weighted = _gaussian(padded_weight * padded, cells, layers)
    return np.divide(weighted, total, out=np.zeros_like(total), where=total > 0)


def isosurface(scalar, color, box, level, cells_offset=0.0, image_velocity=0.0):
    """Triangles where the cell-centred `scalar` [nz, ny, nx] equals `level` inside the box
    (L_x, L_y, L_z), by flying edges on the grid of cell centres padded with one layer of images,
    clipped to the box.  Returns (vertices (V, 3) as x, y, z; triangles (T, 3) vertex indices;
    `color` linearly interpolated at each vertex (V,))."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPlane
    from vtkmodules.vtkFiltersCore import vtkClipPolyData, vtkFlyingEdges3D, vtkTriangleFilter

    nz, ny, nx = scalar.shape
    spacing = (box[0] / nx, box[1] / ny, box[2] / nz)
    image = vtkImageData()
    image.SetDimensions(nx + 2, ny + 2, nz + 2)
    image.SetSpacing(*spacing)
    image.SetOrigin(*(-0.5 * h for h in spacing))
    for name, values, velocity in (("scalar", scalar, 0.0), ("color", color, image_velocity)):
        array = numpy_to_vtk(np.ascontiguousarray(pad(values, 1, cells_offset, velocity), dtype=np.float64).ravel(), deep=True)
        array.SetName(name)
        image.GetPointData().AddArray(array)
    image.GetPointData().SetActiveScalars("scalar")
    surface = vtkFlyingEdges3D()
    surface.SetInputData(image)
    surface.SetValue(0, level)
    surface.ComputeNormalsOff()
    surface.ComputeGradientsOff()
    surface.InterpolateAttributesOn()
    # One plane per face: a plane's implicit function is linear, so its cut along an edge is exact
    # (a vtkBox's is not, near the corners).
    last = surface
    for axis in range(3):
        for side in (0.0, 1.0):
            face = vtkPlane()
            face.SetOrigin(*(side * box[a] if a == axis else 0.0 for a in range(3)))
            face.SetNormal(*((1.0 if side == 0.0 else -1.0) if a == axis else 0.0 for a in range(3)))
            clip = vtkClipPolyData()
            clip.SetInputConnection(last.GetOutputPort())
            clip.SetClipFunction(face)  # keeps the side the normal points to
            last = clip
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(last.GetOutputPort())
    triangles.Update()
    mesh = triangles.GetOutput()
    if mesh.GetNumberOfPolys() == 0:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64), np.zeros(0)
    vertices = vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
    connectivity = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).astype(np.int64).reshape(-1, 3)
    return vertices, connectivity, vtk_to_numpy(mesh.GetPointData().GetArray("color")).astype(np.float64)


def area_and_volume(vertices, triangles):
    """Area of a triangulated surface, and the volume it encloses if it is closed (divergence
    theorem: the sum of signed tetrahedra from the origin, sign-free)."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    return 0.5 * np.linalg.norm(normals, axis=1).sum(), abs(np.einsum("ij,ij->i", a, np.cross(b, c)).sum()) / 6.0
