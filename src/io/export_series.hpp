// A run's frames exported for OVITO and ParaView (`granule plot export`): the snapshots as one
// multi-frame extended XYZ file or as VTK PolyData, a fields file as VTK ImageData; several VTK
// frames become a .pvd series.  Frames are indices ≥ 0 of the input file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace granule {

// Called with each file's path as soon as it is complete.
using ExportWritten = std::function<void(const std::string& path)>;
// Writes frame k to `path` and returns its time.
using ExportFrameWriter = std::function<double(std::int64_t k, const std::string& path)>;

// One frame: `series` itself.  Several: `<stem>_<k>.<extension>` beside `series` for each frame
// k, then the .pvd collection `series` of them.
void write_vtk_series(const std::filesystem::path& series, const std::vector<std::int64_t>& frames,
                      const std::string& extension, const ExportFrameWriter& write_frame, const ExportWritten& written);

// The snapshots' frames as one extended XYZ file (staged: nothing under `out` until complete).
void export_xyz_frames(const std::string& snapshots, const std::vector<std::int64_t>& frames, const std::string& out);

// The snapshots' frames as VTK PolyData (.vtp).
void export_vtp_frames(const std::string& snapshots, const std::vector<std::int64_t>& frames,
                       const std::filesystem::path& out, const ExportWritten& written);

// A fields file's frames as VTK ImageData (.vti), every map of /instant and /average.
void export_field_file_frames(const std::string& fields, const std::vector<std::int64_t>& frames,
                              const std::filesystem::path& out, const ExportWritten& written);

}  // namespace granule
