// The figures python/granule_plots draws from a run's files with matplotlib (`granule plot fields
// | timeseries | profiles | phase | collisions | spectra | f1 | spins`): what a request asks becomes the
// script's arguments, and what it leaves empty keeps the script's default.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace granule::render {

struct FigureRequest {
  std::string input;  // the run's file the script reads
  std::string out;    // PNG
  std::int64_t frame = -1;
  int dpi = 100;
  std::string data;   // the numbers drawn, also written as JSON here ("": not written)
  // fields: 2D maps and 3D isosurfaces
  std::string group = "average";
  std::vector<std::string> quantities;
  std::string colormap = "gray";
  std::string smooth, average_frames;
  // fields of a 3D run only
  std::string level, color_by;
  std::vector<std::string> view, size;
  // phase: at most this many disks, a random subset
  std::int64_t max_points = 200000;
  // collisions, f1: the part of the file drawn
  std::optional<std::string> window;
};

// `script`.py's figure (fields.py draws the maps of a 2D run).  Returns the script's exit code.
int draw_figure(const std::string& script, const FigureRequest& request);

// fields3d.py: the density isosurface of a 3D fields file coloured by V_x (Figs C.1–C.3), with the
// request's colormap only when `colormap_chosen` (the script's own is coolwarm).  Returns its exit code.
int draw_isosurface(const FigureRequest& request, bool colormap_chosen);

}  // namespace granule::render
