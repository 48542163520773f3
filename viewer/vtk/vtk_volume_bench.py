#!/usr/bin/python3
"""VTK 9.1's volume mappers on the views of `volsg-bench --suite node`: the baseline of issue 4.

Renders the volumes, transfer functions and cameras that `volsg-bench --suite node
--export-views DIR` wrote, with vtkOpenGLGPUVolumeRayCastMapper and
vtkFixedPointVolumeRayCastMapper (sample distance 0.5 L0, no automatic adjustment, no
jitter), DVR unshaded and shaded, and MIP. Times every orbit view (Render() and a float
readback of the finished frame, as volsg-bench times render() with its readback), writes the
medians to DIR/vtk-results.tsv and the frames of the compared views as PFM, so that
`volsg-bench --suite node --compare DIR` measures their error against the same reference.

A benchmark baseline only: needs Debian's python3-vtk9 and python3-numpy; VTK renders through
GLX, so run it under Xvfb (which gives llvmpipe, as volsg's OSMesa backend):

    xvfb-run -a -s "-screen 0 1024x768x24" /usr/bin/python3 viewer/vtk/vtk_volume_bench.py DIR

How the rendering model of docs/SCENE-FORMAT.md section 4 is mapped:
- Transfer function: every control point of the colour channels (their union, all three
  channels evaluated there: exact, since each is linear between them) and of alpha, moved from
  v to data values through dataRange; VTK clamps beyond the ends as v does.
- Opacity: A is the opacity of a slab L0 thick, so ScalarOpacityUnitDistance = L0.
- Geometry: the voxel centres coincide. volsg's box reaches half a voxel beyond the outermost
  centres, with the data clamped to the edge there; a VTK image ends at the centres. --pad
  gives the image one replicated voxel layer per side, cropped (cropping planes) to volsg's
  box; measured on Marschner-Lobb 256^3 that made VTK's error larger (RMSE 0.0055 against
  0.0046 without) and its frames slower, so by default VTK keeps its own box.
- Camera: position, focal point, view up, vertical view angle (or parallel scale), near and far
  as volsg-bench used them; the background; a headlight (VTK's default light) with ambient
  0.2, diffuse 1 and no specular, as volsg lights a volume in a scene without lights.
"""

import argparse
import json
import os
import statistics
import sys
import time

import numpy as np
import vtk
from vtk.util import numpy_support


def piecewise(points, x):
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return float(np.interp(x, xs, ys))


def make_property(case, shaded):
    lo, hi = case["dataRange"]
    colour = vtk.vtkColorTransferFunction()
    xs = sorted({p[0] for ch in ("red", "green", "blue") for p in case[ch]} | {lo, hi})
    for x in xs:
        colour.AddRGBPoint(x, *(piecewise(case[ch], x) for ch in ("red", "green", "blue")))
    opacity = vtk.vtkPiecewiseFunction()
    for x in sorted({p[0] for p in case["alpha"]} | {lo, hi}):
        opacity.AddPoint(x, piecewise(case["alpha"], x))
    prop = vtk.vtkVolumeProperty()
    prop.SetColor(colour)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(case["L0"])
    prop.SetInterpolationTypeToLinear()
    prop.SetShade(1 if shaded else 0)
    light = case["lighting"]
    prop.SetAmbient(light["ambient"])
    prop.SetDiffuse(light["diffuse"])
    prop.SetSpecular(light["specular"])
    return prop


def make_image(case, directory, pad):
    nx, ny, nz = case["dimensions"]
    data = np.fromfile(os.path.join(directory, case["raw"]),
                       dtype=np.dtype(case["dtype"]).newbyteorder("<"))
    data = data.reshape(nz, ny, nx)
    if pad:
        data = np.pad(data, 1, mode="edge")
    data = np.ascontiguousarray(data.astype(data.dtype.newbyteorder("=")))
    spacing = case["spacing"]
    extent = [n * s for n, s in zip(case["dimensions"], spacing)]
    # volsg: voxel i at -extent/2 + (i + 0.5) spacing; the padded layer is voxel -1.
    origin = [-e / 2 + s / 2 - (s if pad else 0.0) for e, s in zip(extent, spacing)]
    image = vtk.vtkImageData()
    image.SetDimensions(data.shape[2], data.shape[1], data.shape[0])
    image.SetSpacing(*spacing)
    image.SetOrigin(*origin)
    scalars = numpy_support.numpy_to_vtk(data.ravel(), deep=True)
    scalars.SetName("scalars")
    image.GetPointData().SetScalars(scalars)
    return image, extent


def make_mapper(kind, image, extent, case, mode, pad):
    if kind == "gpu":
        mapper = vtk.vtkOpenGLGPUVolumeRayCastMapper()
        mapper.SetUseJittering(0)
    else:
        mapper = vtk.vtkFixedPointVolumeRayCastMapper()
    mapper.SetInputData(image)
    mapper.SetAutoAdjustSampleDistances(0)
    mapper.SetSampleDistance(0.5 * case["L0"])
    mapper.SetImageSampleDistance(1.0)
    if mode == "MIP":
        mapper.SetBlendModeToMaximumIntensity()
    else:
        mapper.SetBlendModeToComposite()
    if pad:
        half = [e / 2 for e in extent]
        mapper.SetCropping(1)
        mapper.SetCroppingRegionPlanes(-half[0], half[0], -half[1], half[1], -half[2], half[2])
        mapper.SetCroppingRegionFlagsToSubVolume()
    return mapper


def set_camera(camera, view):
    camera.SetPosition(*view["position"])
    camera.SetFocalPoint(*view["focalPoint"])
    camera.SetViewUp(*view["viewUp"])
    if view["orthographic"]:
        camera.ParallelProjectionOn()
        camera.SetParallelScale(view["parallelScale"])
    else:
        camera.ParallelProjectionOff()
        camera.SetViewAngle(view["viewAngle"])
    camera.SetClippingRange(view["near"], view["far"])


def write_pfm(path, rgba, width, height):
    """rgba: float32 RGBA rows bottom to top (glReadPixels order), which is PFM's order."""
    rgb = np.asarray(rgba, dtype="<f4").reshape(height, width, 4)[:, :, :3]
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (width, height))
        f.write(np.ascontiguousarray(rgb).tobytes())


def renderer_string(window):
    for line in window.ReportCapabilities().splitlines():
        if "OpenGL renderer string" in line:
            return line.split(":", 1)[1].strip()
    return "unknown"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("dir", help="the --export-views folder; results are written there too")
    parser.add_argument("--cases", default="", help="comma-separated case names (default all)")
    parser.add_argument("--mappers", default="gpu,cpu", help="gpu, cpu or both")
    parser.add_argument("--kinds", default="DVR-unshaded,DVR-shaded,MIP-unshaded")
    parser.add_argument("--pad", action="store_true",
                        help="a replicated voxel layer per side, cropped to volsg's box")
    args = parser.parse_args()

    with open(os.path.join(args.dir, "views.json")) as f:
        spec = json.load(f)
    width, height = spec["width"], spec["height"]
    wanted = set(filter(None, args.cases.split(",")))

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(*spec["background"])
    window.AddRenderer(renderer)
    window.Render()
    gl = renderer_string(window)
    print("VTK %s, GL renderer: %s, GALLIUM_DRIVER=%s, LP_NUM_THREADS=%s" % (
        vtk.vtkVersion.GetVTKVersion(), gl, os.environ.get("GALLIUM_DRIVER", "(unset)"),
        os.environ.get("LP_NUM_THREADS", "(unset)")), flush=True)
    if "llvmpipe" not in gl:
        print("warning: not rendering on llvmpipe", file=sys.stderr)

    results = []
    for case in spec["cases"]:
        if wanted and case["name"] not in wanted:
            continue
        image, extent = make_image(case, args.dir, args.pad)
        for mapper_kind in args.mappers.split(","):
            for kind in args.kinds.split(","):
                mode, shading = kind.split("-")
                mapper = make_mapper(mapper_kind, image, extent, case, mode, args.pad)
                volume = vtk.vtkVolume()
                volume.SetMapper(mapper)
                volume.SetProperty(make_property(case, shading == "shaded"))
                renderer.AddVolume(volume)
                camera = renderer.GetActiveCamera()
                pixels = vtk.vtkFloatArray()

                def frame(view):
                    set_camera(camera, view)
                    window.Render()
                    window.GetRGBAPixelData(0, 0, width - 1, height - 1, 0, pixels)

                frame(case["views"][0])  # warm-up: shader builds and uploads are not frames
                wall, cpu = [], []
                for index, view in enumerate(case["views"]):
                    t0, c0 = time.perf_counter(), time.process_time()
                    frame(view)
                    wall.append((time.perf_counter() - t0) * 1e3)
                    cpu.append((time.process_time() - c0) * 1e3)
                    if index in case["errorViews"]:
                        name = "vtk-%s-%s-%s-%s-view%d.pfm" % (case["name"], mode, mapper_kind,
                                                               shading, index)
                        write_pfm(os.path.join(args.dir, name),
                                  numpy_support.vtk_to_numpy(pixels), width, height)
                row = (case["name"], mode, mapper_kind, shading, statistics.median(wall),
                       statistics.median(cpu), len(wall), gl)
                print("%-10s %-4s %-4s %-9s median %8.1f ms/frame (min %.1f), process CPU "
                      "%8.1f ms/frame, %d frames" % (row[:5] + (min(wall), row[5], len(wall))),
                      flush=True)
                results.append(row)
                renderer.RemoveVolume(volume)
                mapper.ReleaseGraphicsResources(window)

    with open(os.path.join(args.dir, "vtk-results.tsv"), "w") as f:
        f.write("# case\tmode\tmapper\tshading\tmedian_ms\tmedian_process_cpu_ms\tframes\t"
                "renderer\n")
        for row in results:
            f.write("%s\t%s\t%s\t%s\t%.3f\t%.3f\t%d\t%s\n" % row)
    print("wrote", os.path.join(args.dir, "vtk-results.tsv"))


if __name__ == "__main__":
    main()
