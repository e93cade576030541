// The OpenGL backends: EGL and OSMesa each make a context that says what it is, draw the same
// bytes on llvmpipe, and fail with words that say what to do; a GPU where EGL lists one.
#include "render/gl_context.h"
#include "render/renderer.h"
#include "tests/support/render_scenes.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace impulse {
namespace {

// Sets IMPULSE_GL for a scope (a Renderer makes its context from it, as the program's do).
class GlEnvironment {
 public:
  explicit GlEnvironment(const char* backend) {
    if (const char* was = std::getenv("IMPULSE_GL")) was_ = was;
    setenv("IMPULSE_GL", backend, 1);
  }
  ~GlEnvironment() {
    if (was_.empty()) unsetenv("IMPULSE_GL");
    else setenv("IMPULSE_GL", was_.c_str(), 1);
  }

 private:
  std::string was_;
};

TEST(GlContext, EachBackendSaysWhatItIsAndWhatDraws) {
  {
    const render::GlContext context(render::GlBackend::egl, -1);
    EXPECT_EQ(context.info().backend, render::GlBackend::egl);
    EXPECT_NE(context.info().device.find(render::egl_gpu_count() > 0 ? "hardware" : "software"), std::string::npos)
        << context.info().device;
    EXPECT_NE(context.info().version.find("4.5"), std::string::npos) << context.info().version;
    EXPECT_FALSE(context.info().renderer.empty());
  }
  if (!render::osmesa_built()) GTEST_SKIP() << "built without OSMesa (IMPULSE_OSMESA=OFF)";
  const render::GlContext context(render::GlBackend::osmesa, -1);
  EXPECT_EQ(context.info().backend, render::GlBackend::osmesa);
  EXPECT_EQ(context.info().device, "OSMesa");
  EXPECT_NE(context.info().renderer.find("llvmpipe"), std::string::npos) << context.info().renderer;
}

// The same driver behind both: the same frame to the byte, shadows, impostors and edges included.
TEST(GlContext, EglAndOsmesaDrawTheSameBytesOnLlvmpipe) {
  if (!render::osmesa_built()) GTEST_SKIP() << "built without OSMesa (IMPULSE_OSMESA=OFF)";
  if (render::egl_gpu_count() > 0) GTEST_SKIP() << "EGL draws on a GPU here, not llvmpipe";
  const render::DrawList scene = testing::bodies_scene();
  render::Frame egl, osmesa;
  {
    const GlEnvironment environment("egl");
    render::Renderer renderer(320, 240);
    egl = renderer.draw(scene);
  }
  {
    const GlEnvironment environment("osmesa");
    render::Renderer renderer(320, 240);
    osmesa = renderer.draw(scene);
  }
  ASSERT_EQ(egl.rgba.size(), size_t(320) * 240 * 4);
  size_t lit = 0;
  for (size_t i = 0; i < egl.rgba.size(); i += 4) lit += egl.rgba[i] != egl.rgba[0] || egl.rgba[i + 1] != egl.rgba[1];
  EXPECT_GT(lit, 10000u) << "a scene was drawn, not a cleared frame";
  EXPECT_TRUE(egl.rgba == osmesa.rgba);
}

TEST(GlContext, ABackendOrGpuThatIsNotThereIsAnErrorThatSaysSo) {
  try {
    render::parse_gl_backend("vulkan");
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("auto, egl or osmesa"), std::string::npos) << error.what();
  }
  const int gpus = render::egl_gpu_count();
  try {
    const render::GlContext context(render::GlBackend::egl, gpus + 3);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("no GPU " + std::to_string(gpus + 3)), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("leave --gpu out"), std::string::npos) << error.what();
  }
}

// Where EGL lists a GPU, the automatic choice draws on it, not on llvmpipe.
TEST(GlContext, AGpuIsChosenWhereThereIsOne) {
  if (render::egl_gpu_count() == 0) GTEST_SKIP() << "no GPU here: EGL lists no hardware device";
  const render::GlContext context(render::GlBackend::automatic, -1);
  EXPECT_EQ(context.info().backend, render::GlBackend::egl);
  EXPECT_NE(context.info().device.find("hardware"), std::string::npos) << context.info().device;
  EXPECT_EQ(context.info().renderer.find("llvmpipe"), std::string::npos) << context.info().renderer;
}

}  // namespace
}  // namespace impulse
