// What shows the spin of rough grains and the walls: the angular velocity column of extended XYZ
// (`omega`) and the "AngularVelocity" array of .vtp files, pictures coloured by ω_z on a scale
// centred on 0 (thesis Fig C.4), and walls drawn as lines on their faces (Fig C.5).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <cstring>
#include <cstdint>

#include "io/export_vtk.hpp"
#include "io/export_xyz.hpp"
#include "render/color_scales.hpp"
#include "render/configuration_picture.hpp"
#include "unit/particle_rows.hpp"

namespace granule {
namespace {

ParticleState two_spinning_disks() {
  ParticleState p = particles_from_rows({{0.25, 0.5, 1.0, 0.0}, {0.75, 0.5, 0.0, -1.0}});
  p.wz = {2.0, -2.0};
  return p;
}

TEST(RoughExports, ExtendedXyzCarriesOmega) {
  std::ostringstream out;
  XyzFrameInfo info;
  info.diameter = 0.2;
  write_xyz_frame(out, two_spinning_disks(), info);
  const std::string text = out.str();
  EXPECT_NE(text.find("Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1:omega:R:3 "), std::string::npos) << text;
  EXPECT_NE(text.find("\nD 0.75 0.5 0 0 -1 0 0.1 0 0 -2\n"), std::string::npos) << text;

  std::ostringstream smooth;
  ParticleState plain = two_spinning_disks();
  plain.wz.clear();
  write_xyz_frame(smooth, plain, info);
  EXPECT_EQ(smooth.str().find("omega"), std::string::npos);
  EXPECT_NE(smooth.str().find("\nD 0.75 0.5 0 0 -1 0 0.1\n"), std::string::npos);
}

TEST(RoughExports, ExtendedXyzOfSpheresHasAllThreeComponents) {
  ParticleState p;
  p.dimension = 3;
  p.x = p.y = p.z = {0.5};
  p.vx = p.vy = p.vz = {0.0};
  p.wx = {1.5};
  p.wy = {-2.5};
  p.wz = {3.5};
  std::ostringstream out;
  XyzFrameInfo info;
  info.diameter = 0.2;
  write_xyz_frame(out, p, info);
  EXPECT_NE(out.str().find("\nD 0.5 0.5 0.5 0 0 0 0.1 1.5 -2.5 3.5\n"), std::string::npos) << out.str();
}

TEST(RoughExports, VtpHasAnAngularVelocityArray) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "granule_test_rough_exports";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "particles.vtp").string();
  write_vtp_particles(path, two_spinning_disks(), 0.2, 1.0);
  std::ifstream in(path, std::ios::binary);
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t header = content.find("Name=\"AngularVelocity\" NumberOfComponents=\"3\"");
  ASSERT_NE(header, std::string::npos);
  // Its appended block: 8-byte size, then (0, 0, ω_z) per disk.
  const std::size_t offset_at = content.find("offset=\"", header) + 8;
  const std::size_t offset = std::stoul(content.substr(offset_at));
  const std::size_t data = content.find("<AppendedData encoding=\"raw\">\n_") + 31;
  std::uint64_t size = 0;
  std::memcpy(&size, content.data() + data + offset, sizeof size);
  ASSERT_EQ(size, 6 * sizeof(double));
  double values[6];
  std::memcpy(values, content.data() + data + offset + sizeof size, sizeof values);
  EXPECT_EQ(values[0], 0.0);
  EXPECT_EQ(values[1], 0.0);
  EXPECT_EQ(values[2], 2.0);
  EXPECT_EQ(values[5], -2.0);
}

void expect_color(const render::Pixel& p, const render::Rgb& c) {
  EXPECT_NEAR(p.r, 255.0 * c.r, 1.5);
  EXPECT_NEAR(p.g, 255.0 * c.g, 1.5);
  EXPECT_NEAR(p.b, 255.0 * c.b, 1.5);
}

render::PictureOptions spin_picture(int width) {
  render::PictureOptions o;
  o.width_px = width;
  o.arrows = false;
  o.legend = false;
  o.coloring = render::DiskColoring::kSpin;
  return o;
}

TEST(RoughPictures, SpinColoursAreCentredOnZero) {
  // Opposite spins get the two ends of the diverging scale; ω = 0 its (near-white) middle.
  const ParticleState p = two_spinning_disks();
  const render::RasterImage image = render::render_configuration({p, 0.2, ShearFrame{1.0, 1.0, 0.0}, 0.0}, spin_picture(200));
  expect_color(image.at(50, 100), render::diverging_color(1.0));
  expect_color(image.at(150, 100), render::diverging_color(-1.0));
  const render::Rgb middle = render::diverging_color(0.0);
  EXPECT_GT(middle.r, 0.9);
  EXPECT_GT(middle.b, 0.9);
  EXPECT_GT(render::diverging_color(1.0).r, render::diverging_color(1.0).b);   // positive: red
  EXPECT_LT(render::diverging_color(-1.0).r, render::diverging_color(-1.0).b); // negative: blue
}

TEST(RoughPictures, SmoothGrainsHaveNoSpinColours) {
  ParticleState p = two_spinning_disks();
  p.wz.clear();
  EXPECT_THROW(render::render_configuration({p, 0.2, ShearFrame{1.0, 1.0, 0.0}, 0.0}, spin_picture(200)), std::invalid_argument);
}

TEST(RoughPictures, WallsAreLinesOnTheirFaces) {
  const ParticleState p = two_spinning_disks();
  render::PictureOptions options = spin_picture(200);
  const render::RasterImage walled =
      render::render_configuration({p, 0.2, ShearFrame{1.0, 1.0, 0.0}, 0.0, {false, true}}, options);
  const auto black = [](const render::Pixel& px) { return px.r < 40 && px.g < 40 && px.b < 40; };
  EXPECT_TRUE(black(walled.at(100, 0)));    // the ceiling y = L_y
  EXPECT_TRUE(black(walled.at(100, 199)));  // the floor y = 0
  EXPECT_FALSE(black(walled.at(0, 100)));   // no x walls
  const render::RasterImage open = render::render_configuration({p, 0.2, ShearFrame{1.0, 1.0, 0.0}, 0.0}, options);
  EXPECT_FALSE(black(open.at(100, 0)));
}

}  // namespace
}  // namespace granule
