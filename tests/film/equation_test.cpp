// Typeset equations: LaTeX through dvisvgm to SVG, cached by the document's hash, drawn by librsvg
// into the overlay; [[equation]] tables and the eq. 8 panel in whole scenes; TeX errors as scene
// errors with the file and line.
#include "demos/film/live_equations.h"
#include "demos/film/render_scene.h"
#include "demos/film/scene_film.h"
#include "render/overlay_painter.h"
#include "render/png_io.h"
#include "tests/support/scene_scratch.h"
#include "tex/tex_typesetter.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <thread>

namespace impulse {
namespace {

namespace fs = std::filesystem;
using testing::scratch;

// The overlay's ink (render/panel_painter.cpp: 0.13, 0.13, 0.15), at least half covering a pixel
// of the white panel: a dark neutral grey.
bool inked(const render::Frame& frame, int x, int y) {
  const testing::Rgb p = testing::pixel(frame, x, y);
  return p.r < 145 && std::abs(p.r - p.g) < 8 && p.b >= p.r && p.b - p.r < 14;
}
int inked_pixels(const render::Frame& frame, int x0, int y0, int x1, int y1) {
  int count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) count += inked(frame, x, y);
  return count;
}

TEST(Tex, TypesetsAnExpressionIntoAnSvgOfPaths) {
  tex::TexTypesetter typesetter(tex::TexCache(scratch("tex_test", "simple").string()));
  const auto math = typesetter.typeset("J = \\frac{-(1+e)\\,v_{ab}\\cdot\\hat n}{1/m_a + 1/m_b}");
  EXPECT_NE(math->svg.find("<svg"), std::string::npos);
  EXPECT_NE(math->svg.find("<path"), std::string::npos) << "--no-fonts: glyphs as paths";
  EXPECT_EQ(math->svg.find("<font"), std::string::npos);
  EXPECT_EQ(math->key.size(), 16u);
}

// A painted panel of typeset mathematics: ink where it is placed, nothing elsewhere.
TEST(Tex, APanelOfMathematicsIsInkedWhereItIsPlaced) {
  tex::TexTypesetter typesetter(tex::TexCache(scratch("tex_test", "panel").string()));
  const auto math = typesetter.typeset("x^2 + y^2 = r^2");
  render::Overlay overlay;
  render::OverlayPanel panel;
  panel.corner = {400, 300};
  panel.math = {math->key, std::shared_ptr<const std::string>(math, &math->svg), "", 2.0f};
  overlay.panels.push_back(panel);
  render::Frame frame{640, 480, std::vector<uint8_t>(size_t(640) * 480 * 4, 255)};
  render::OverlayPainter painter(640, 480);
  painter.paint(overlay, frame);
  render::write_png((scratch("tex_test", "panel_frame") / "frame.png").string(), frame);  // to look at
  // About 70 x 14 pt at 2 px/pt x 480/720: some 95 x 20 pixels of letters, right of and under the corner.
  EXPECT_GT(inked_pixels(frame, 400, 300, 560, 360), 150);
  EXPECT_EQ(inked_pixels(frame, 0, 0, 640, 295), 0);
  EXPECT_EQ(inked_pixels(frame, 0, 0, 395, 480), 0);
}

TEST(Tex, TheSecondTypesettingIsACacheHitWithoutLatex) {
  const fs::path cache = scratch("tex_test", "cache");
  const std::string expression = "E = \\tfrac{1}{2} m v^2";
  std::string first_svg;
  {
    tex::TexTypesetter typesetter{tex::TexCache(cache.string())};
    first_svg = typesetter.typeset(expression)->svg;
    EXPECT_EQ(typesetter.latex_runs(), 1);
    typesetter.typeset(expression);  // in memory
    EXPECT_EQ(typesetter.latex_runs(), 1);
  }
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(cache)) {
    ++files;
    EXPECT_EQ(entry.path().extension(), ".svg") << "no temporary left: " << entry.path();
  }
  EXPECT_EQ(files, 1u);
  const auto written = fs::last_write_time(*fs::directory_iterator(cache));
  tex::TexTypesetter again{tex::TexCache(cache.string())};  // a new process, as it were
  EXPECT_EQ(again.typeset(expression)->svg, first_svg);
  EXPECT_EQ(again.latex_runs(), 0) << "the cache on disk is hit";
  EXPECT_EQ(fs::last_write_time(*fs::directory_iterator(cache)), written);
}

// Renders typesetting at once into one cache: each gets its SVG, the cache holds whole files only.
TEST(Tex, ConcurrentTypesettersShareTheCacheSafely) {
  const fs::path cache = scratch("tex_test", "concurrent");
  std::vector<std::string> results(4);
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i)
    threads.emplace_back([&, i] {
      tex::TexTypesetter typesetter{tex::TexCache(cache.string())};
      results[i] = typesetter.typeset(i % 2 ? "a^2 + b^2 = c^2" : "\\sqrt{2}")->svg;
    });
  for (std::thread& thread : threads) thread.join();
  for (int i = 0; i < 4; ++i) EXPECT_EQ(results[i], results[i % 2]);
  for (const auto& entry : fs::directory_iterator(cache)) EXPECT_EQ(entry.path().extension(), ".svg");
  EXPECT_EQ(tex::TexCache(cache.string()).read(tex::text_hash(tex::TexTypesetter::document("\\sqrt{2}"))), results[0]);
}

TEST(Tex, LatexErrorsAreReportedInOneLine) {
  tex::TexTypesetter typesetter(tex::TexCache(scratch("tex_test", "errors").string()));
  auto error_of = [&](const std::string& expression) {
    try {
      typesetter.typeset(expression);
    } catch (const tex::TexError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("J = \\fracc{1}{2}"), "LaTeX: Undefined control sequence \\fracc");
  EXPECT_EQ(error_of("x^{2"), "LaTeX: Missing } inserted after 'x^{2'");
  EXPECT_NE(error_of("a $ b").find("a '$' in the expression"), std::string::npos);
}

// An endless TeX loop is stopped at the time limit, with the whole process group.
TEST(Tex, AnEndlessLoopIsStoppedAtTheTimeLimit) {
  tex::TexTypesetter typesetter(tex::TexCache(scratch("tex_test", "endless").string()), 1.0);
  const auto start = std::chrono::steady_clock::now();
  try {
    typesetter.typeset("\\loop\\iftrue\\repeat");
    FAIL() << "no error";
  } catch (const tex::TexError& error) {
    EXPECT_NE(std::string(error.what()).find("took longer than 1 s"), std::string::npos) << error.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST(Tex, NoLatexSaysWhatToInstall) {
  const std::string path = std::getenv("PATH");
  setenv("PATH", scratch("tex_test", "empty_path").c_str(), 1);
  tex::TexTypesetter typesetter(tex::TexCache(scratch("tex_test", "no_latex").string()));
  std::string message;
  try {
    typesetter.typeset("x");
  } catch (const tex::TexError& error) {
    message = error.what();
  }
  setenv("PATH", path.c_str(), 1);
  EXPECT_NE(message.find("cannot run latex"), std::string::npos) << message;
  EXPECT_NE(message.find("apt-get install texlive-latex-base dvisvgm"), std::string::npos) << message;
}

constexpr const char* kEquationScene = R"([scene]
duration = 1.0
[video]
width = 640
height = 360
fps = 10
[overlay]
title = false
clock = false
legend = false
[[body]]
shape = "plane"
[[equation]]
tex = 'J = \frac{-(1+e)\,v_{ab}\cdot\hat n}{1/m_a + 1/m_b}'
start = 0.3
end = 0.7
position = "bottom-right"
size = 30
)";

TEST(Tex, AnEquationTableIsInkedInItsCornerDuringItsCue) {
  const fs::path dir = scratch("tex_test", "scene");
  const demos::Scene scene = testing::scene_from(dir, kEquationScene);
  ASSERT_EQ(scene.equations.size(), 1u);
  demos::check_equations(scene);
  demos::RenderOptions options;
  options.png_directory = (dir / "frames").string();
  demos::render_scene(scene, options);
  // Nothing moves: the frames differ by the equation's panel alone.
  auto frame_png = [&](int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frame);
    return render::read_png((dir / "frames" / name).string());
  };
  const render::Frame without = frame_png(0);
  for (int frame = 1; frame < 10; ++frame) {
    const render::Frame image = frame_png(frame);
    int changed_outside = 0, inked_corner = 0;
    for (int y = 0; y < 360; ++y)
      for (int x = 0; x < 640; ++x) {
        const bool changed = std::memcmp(&image.rgba[(size_t(y) * 640 + x) * 4], &without.rgba[(size_t(y) * 640 + x) * 4], 3) != 0;
        const bool corner = x >= 320 && y >= 180;
        if (changed && !corner) ++changed_outside;
        if (changed && corner && inked(image, x, y)) ++inked_corner;
      }
    EXPECT_EQ(changed_outside, 0) << "frame " << frame;
    if (frame >= 4 && frame <= 6) {
      EXPECT_GT(inked_corner, 300) << "frame " << frame << ": the equation's letters";
    }
    if (frame < 3 || frame > 7) {
      EXPECT_EQ(inked_corner, 0) << "frame " << frame << ": outside its cue";
    }
  }
}

TEST(Tex, BadTexIsASceneErrorWithFileAndLine) {
  const fs::path dir = scratch("tex_test", "bad");
  std::string text = kEquationScene;
  text.replace(text.find("\\frac{"), 6, "\\fracc{");
  const demos::Scene scene = testing::scene_from(dir, text);  // the loader runs no latex
  try {
    demos::check_equations(scene);
    FAIL() << "no error";
  } catch (const demos::SceneError& error) {
    EXPECT_EQ(std::string(error.what()),
              (dir / "scene.toml").string() + ":14: [[equation]] 1 field 'tex': LaTeX: Undefined control sequence \\fracc");
  }
}

TEST(Tex, LiveValuesNeedImpactsThatSlowTheVideo) {
  const fs::path dir = scratch("tex_test", "live");
  std::string text = kEquationScene;
  text.replace(text.find("\\frac{-(1+e)"), 0, "{e} = ");
  EXPECT_THROW(testing::scene_from(dir, text), demos::SceneError);
}

TEST(Tex, LiveValuesAreFilledInBraces) {
  demos::ImpactNumbers impact;
  impact.time = 0.8;
  impact.restitution = 0.7;
  impact.point_approach = -3;
  impact.inverse_mass_a = 1;
  impact.inverse_mass_b = 0;  // static
  impact.impulse = 5.1;
  EXPECT_EQ(demos::fill_live_values("x^{e} + {vab} \\{e\\} {J}/{ma}/{mb} {Jsolver}", impact),
            "x^{0.70} + {-3.00} \\{e\\} {5.10}/{1.00}/{\\infty} {5.10}");
}

// Section 3 at e = 0.7: the panel's TeX, read before typesetting, has the hit's numbers.
TEST(Tex, TheEq8PanelOfSection3ShowsTheHitsNumbers) {
  const demos::Scene scene =
      demos::load_scene("assets/scenes/s3_restitution.toml", {"body[light].restitution=0.7", "video.quality=low"});
  demos::SceneFilm film(scene, 854, 480);
  std::string tex;
  demos::ScenePicture picture;
  while (film.next_picture() < film.picture_count() && tex.empty()) {
    film.next(picture);
    for (const render::OverlayPanel& panel : picture.overlay.panels)
      if (panel.math.svg && !panel.lines.empty() && panel.lines[0].rfind("eq. 8 at t = ", 0) == 0) tex = panel.math.tex;
  }
  ASSERT_FALSE(tex.empty()) << "no eq. 8 panel";
  EXPECT_NE(tex.find("\\frac{-(1+0.70)\\,(-3.00)}{1/1.00 + 1/2.00} = 3.40"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\text{solver: } 3.40"), std::string::npos) << tex;
  EXPECT_NE(tex.find("-(1-e)\\text{: } 0.60"), std::string::npos) << tex;
}

}  // namespace
}  // namespace impulse
