// The renderer probe (render/renderer_probe.h): software rasterisers are told apart from GPUs by
// their GL_RENDERER string, and the viewport drops multisampling and the depth-of-field blur on
// them by default; under Xvfb the probe
// finds Mesa's software renderer.
#include "gui/render/renderer_probe.h"
#include "gui/render/surface_format.h"

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

TEST(RendererProbe, SoftwareRasterisersAreToldFromGpus) {
  EXPECT_TRUE(isSoftwareRenderer(QStringLiteral("llvmpipe (LLVM 15.0.6, 256 bits)")));
  EXPECT_TRUE(isSoftwareRenderer(QStringLiteral("softpipe")));
  EXPECT_TRUE(isSoftwareRenderer(QStringLiteral("Google SwiftShader")));
  EXPECT_TRUE(isSoftwareRenderer(QStringLiteral("GDI Generic")));
  EXPECT_TRUE(isSoftwareRenderer(QStringLiteral("Apple Software Renderer")));
  EXPECT_FALSE(isSoftwareRenderer(QStringLiteral("Mesa Intel(R) UHD Graphics 620 (KBL GT2)")));
  EXPECT_FALSE(isSoftwareRenderer(QStringLiteral("NVIDIA GeForce RTX 3060/PCIe/SSE2")));
  EXPECT_FALSE(isSoftwareRenderer(QStringLiteral("AMD Radeon RX 6600 (navi23, LLVM 15.0.6, DRM 3.49)")));
  EXPECT_FALSE(isSoftwareRenderer(QString()));
}

TEST(RendererProbe, OnlyAGpuGetsMultisampling) {
  EXPECT_EQ(microscopeSamplesFor(QStringLiteral("llvmpipe (LLVM 15.0.6, 256 bits)")), 0);
  EXPECT_EQ(microscopeSamplesFor(QStringLiteral("NVIDIA GeForce RTX 3060/PCIe/SSE2")), kMicroscopeSamples);
}

TEST(RendererProbe, OnlyAGpuBlursOffTheFocalPlaneByDefault) {
  EXPECT_FALSE(depthOfFieldByDefault(QStringLiteral("llvmpipe (LLVM 15.0.6, 256 bits)")));
  EXPECT_TRUE(depthOfFieldByDefault(QStringLiteral("NVIDIA GeForce RTX 3060/PCIe/SSE2")));
}

TEST(RendererProbe, UnderXvfbTheProbeFindsMesasSoftwareRenderer) {
  const QString renderer = openGlRendererName();
  ASSERT_FALSE(renderer.isEmpty());
  EXPECT_TRUE(isSoftwareRenderer(renderer)) << renderer.toStdString();
  EXPECT_EQ(microscopeSamplesFor(renderer), 0);
}

}  // namespace
}  // namespace microsim::gui
