#include <glad/gl.h>

#include "CoinSuite.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <volsg/actions/SearchAction.h>
#include <volsg/context/Context.h>
#include <volsg/core/Error.h>
#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/Renderbuffer.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Transform.h>

#include "CoinScene.h"
#include "CoinSide.h"
#include "SceneGenerators.h"
#include "Timing.h"

namespace volsg::bench {

namespace {

namespace fs = std::filesystem;

const char* kSampleModels = "/usr/share/inventor/data/models";

struct Case {
    std::string name;
    std::string path; ///< the file both renderers read
    bool edit = false;
};

/// volsg's side of a case: its own context, renderer and graph.
class VolsgScene {
public:
    VolsgScene(const std::string& path, const CoinSuiteSettings& st)
        : root_(readScene(path)), context_(Context::createOffscreen(Backend::OSMesa)),
          renderer_(std::make_unique<Renderer>()) {
        options_.width = st.width;
        options_.height = st.height;
        options_.debug = st.debug;
        readBack_ = st.readBack;
        const std::vector<Node*> transforms = findAll(*root_, Transform::classType());
        if (!transforms.empty()) {
            edited_ = static_cast<Transform*>(transforms[transforms.size() / 2]);
            editedTranslation_ = edited_->translation();
        }
    }
    ~VolsgScene() {
        context_->makeCurrent();
        window_ = Framebuffer();
        windowColor_ = Renderbuffer();
        renderer_.reset(); // its GL objects go with the context current
    }
    /// The frame a user waits for: into a window's 8-bit colour buffer (a framebuffer of the
    /// frame's size standing in for the viewer's back buffer, which Coin's OSMesa buffer is
    /// too), or with --read-back as float pixels (Renderer::render).
    double frameMs() {
        context_->makeCurrent();
        if (!readBack_ && !window_) {
            windowColor_ = Renderbuffer(GL_RGBA8, options_.width, options_.height);
            window_ = Framebuffer::create();
            window_.attach(GL_COLOR_ATTACHMENT0, windowColor_);
            window_.requireComplete("the coin suite's window stand-in");
        }
        return timeMs([&] {
            if (readBack_) {
                renderer_->render(*root_, options_);
                return;
            }
            window_.bind();
            renderer_->renderToBoundFramebuffer(*root_, options_);
            glFinish(); // llvmpipe draws on demand: the frame is done when GL is
        });
    }
    bool editTransform(float offset) {
        if (!edited_) return false;
        edited_->translation = editedTranslation_ + glm::vec3(offset, 0.0f, 0.0f);
        return true;
    }
    /// The last frame's pixels (the window's 8 bits, or the float read-back).
    Image image() {
        context_->makeCurrent();
        return renderer_->readImage();
    }
    const RenderStats& stats() const { return renderer_->stats(); }

private:
    ref_ptr<Node> root_;
    std::unique_ptr<Context> context_;
    std::unique_ptr<Renderer> renderer_;
    Renderbuffer windowColor_;
    Framebuffer window_;
    RenderOptions options_;
    bool readBack_ = false;
    Transform* edited_ = nullptr;
    glm::vec3 editedTranslation_{0.0f};
};

std::string writeFile(const fs::path& dir, const std::string& name, const std::string& text) {
    const fs::path path = dir / name;
    std::ofstream(path) << text;
    return path.string();
}

/// The models case's files: each given file, or every *.iv under a given folder, sorted.
std::vector<std::string> modelFiles(const std::vector<std::string>& given) {
    std::vector<std::string> out;
    for (const std::string& g : given) {
        if (fs::is_directory(g)) {
            std::vector<std::string> found;
            for (const auto& e : fs::recursive_directory_iterator(g))
                if (e.is_regular_file() && e.path().extension() == ".iv")
                    found.push_back(e.path().string());
            std::sort(found.begin(), found.end());
            out.insert(out.end(), found.begin(), found.end());
        } else {
            out.push_back(g);
        }
    }
    return out;
}

std::vector<std::string> defaultModels() {
    std::vector<std::string> out;
    for (const char* m : {"engine.iv", "robots/robotcop.iv", "vehicles/spacestation.iv",
                          "scenes/chesschairs.iv", "household/teapot.iv", "geography/earth.iv"})
        if (fs::exists(fs::path(kSampleModels) / m))
            out.push_back((fs::path(kSampleModels) / m).string());
    return out;
}

bool wanted(const CoinSuiteSettings& st, const std::string& name) {
    return st.cases.empty() || std::find(st.cases.begin(), st.cases.end(), name) != st.cases.end();
}

std::vector<Case> makeCases(const CoinSuiteSettings& st, const fs::path& dir) {
    std::vector<Case> cases;
    if (wanted(st, "grid") || wanted(st, "grid-edit")) {
        const std::string grid = writeFile(dir, "grid.iv", generateGridScene(100));
        if (wanted(st, "grid")) cases.push_back({"grid 100x100", grid, false});
        if (wanted(st, "grid-edit")) cases.push_back({"grid 100x100, 1 edit/frame", grid, true});
    }
    if (wanted(st, "grid100k") || wanted(st, "grid100k-edit")) {
        const std::string grid = writeFile(dir, "grid100k.iv", generateGridScene(317));
        if (wanted(st, "grid100k")) cases.push_back({"grid 317x317 (100k)", grid, false});
        if (wanted(st, "grid100k-edit"))
            cases.push_back({"grid 317x317, 1 edit/frame", grid, true});
    }
    const auto framed = [&](const std::string& model) {
        std::string name = fs::relative(model, kSampleModels).string();
        if (name.empty() || name.starts_with("..")) name = fs::path(model).filename().string();
        std::string flat = name;
        std::replace(flat.begin(), flat.end(), '/', '_');
        const std::string path = (dir / (flat + ".framed.iv")).string();
        coincompare::frameWithCoin(model, path, st.width, st.height,
                                   coincompare::FramingView::Front);
        return Case{name, path, false};
    };
    if (wanted(st, "cone")) {
        const std::string cone = (fs::path(kSampleModels) / "simple/cone.iv").string();
        if (fs::exists(cone)) cases.push_back(framed(cone));
    }
    if (wanted(st, "models")) {
        const std::vector<std::string> models =
            st.models.empty() ? defaultModels() : modelFiles(st.models);
        for (const std::string& m : models) {
            try {
                cases.push_back(framed(m));
            } catch (const std::exception& e) {
                std::printf("%-32s skipped: %s\n", m.c_str(), e.what());
            }
        }
    }
    return cases;
}

struct Row {
    std::string name;
    double coinMs = 0.0, volsgMs = 0.0;
    double meanDifference = 0.0; ///< mean |Coin - volsg| over all pixels and RGB, 0..255
    std::size_t litShapes = 0, vertexLitShapes = 0; ///< volsg's last frame
    /// volsg's GPU bytes for the shapes (shared meshes + per-instance buffer), and the
    /// scene's vertex data drawn (each shape's mesh counted for each time it is drawn).
    std::size_t gpuBytes = 0, vertexBytes = 0;
};

double meanDifference(const std::vector<unsigned char>& coin, const Image& volsg) {
    double sum = 0.0;
    for (std::size_t i = 0; i < volsg.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = std::round(std::clamp(volsg.pixels[i][c], 0.0f, 1.0f) * 255.0);
            sum += std::abs(v - double(coin[i * 4 + std::size_t(c)]));
        }
    return volsg.pixels.empty() ? 0.0 : sum / (3.0 * double(volsg.pixels.size()));
}

void writeCoinPng(const std::string& path, const std::vector<unsigned char>& rgba, int w, int h) {
    Image image(w, h);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = glm::vec4(rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2], 255) / 255.0f;
    writePng(path, image);
}

Row runCase(const Case& c, const CoinSuiteSettings& st, const fs::path& dir) {
    CoinScene coin(c.path, st.width, st.height);
    VolsgScene volsg(c.path, st);
    // Warm-up: programs, uploads and caches are not frames.
    for (int i = 0; i < 3; ++i) {
        coin.frameMs();
        volsg.frameMs();
    }
    Samples coinMs, volsgMs;
    for (int i = 0; i < st.frames; ++i) {
        const float offset = (i % 2) ? 0.3f : 0.0f;
        // Alternate which goes first, so neither always follows the other's cache misses.
        for (int k = 0; k < 2; ++k) {
            if ((i + k) % 2 == 0) {
                coinMs.ms.push_back(timeMs([&] {
                    if (c.edit) coin.editTransform(offset);
                    coin.frameMs();
                }));
            } else {
                volsgMs.ms.push_back(timeMs([&] {
                    if (c.edit) volsg.editTransform(offset);
                    volsg.frameMs();
                }));
            }
        }
    }
    volsg.frameMs(); // the image compared is a frame as timed
    Row row{c.name, coinMs.median(), volsgMs.median()};
    row.litShapes = volsg.stats().litShapes;
    row.vertexLitShapes = volsg.stats().vertexLitShapes;
    row.gpuBytes = volsg.stats().meshBytes + volsg.stats().instanceBytes;
    row.vertexBytes = volsg.stats().drawnMeshBytes;
    const Image image = volsg.image();
    coin.frameMs();
    const std::vector<unsigned char> coinPixels = coin.pixels();
    row.meanDifference = meanDifference(coinPixels, image);
    if (!st.keepDir.empty()) {
        std::string flat = c.name;
        for (char& ch : flat)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        writePng((dir / (flat + ".volsg.png")).string(), image);
        writeCoinPng((dir / (flat + ".coin.png")).string(), coinPixels, st.width, st.height);
    }
    return row;
}

} // namespace

int runCoinSuite(const CoinSuiteSettings& st) {
    const fs::path dir =
        st.keepDir.empty() ? fs::temp_directory_path() / "volsg-bench-coin" : fs::path(st.keepDir);
    fs::create_directories(dir);
    const std::vector<Case> cases = makeCases(st, dir);
    std::printf("%dx%d, %d alternating frames per renderer; Coin: SoGLRenderAction (caching "
                "AUTO) + glFinish; volsg: %s\n",
                st.width, st.height, st.frames,
                st.readBack ? "Renderer::render (read back)"
                            : "Renderer::renderToBoundFramebuffer (an 8-bit window) + glFinish");
    std::printf("%-34s %10s %10s %8s %8s %13s %17s\n", "case", "Coin ms", "volsg ms", "Coin/v",
                "diff", "vertex-lit", "GPU/vertex KB");
    std::vector<double> ratios;
    int ran = 0;
    for (const Case& c : cases) {
        try {
            const Row row = runCase(c, st, dir);
            const double ratio = row.coinMs / std::max(row.volsgMs, 1e-9);
            ratios.push_back(ratio);
            const std::string lit =
                std::to_string(row.vertexLitShapes) + "/" + std::to_string(row.litShapes);
            const std::string memory = std::to_string((row.gpuBytes + 512) / 1024) + "/" +
                                       std::to_string((row.vertexBytes + 512) / 1024);
            std::printf("%-34s %10.3f %10.3f %8.2f %8.2f %13s %17s\n", row.name.c_str(), row.coinMs,
                        row.volsgMs, ratio, row.meanDifference, lit.c_str(), memory.c_str());
            std::fflush(stdout);
            ++ran;
        } catch (const std::exception& e) {
            std::printf("%-34s failed: %s\n", c.name.c_str(), e.what());
        }
    }
    if (ratios.size() > 1) {
        std::vector<double> s = ratios;
        std::sort(s.begin(), s.end());
        const std::size_t n = s.size();
        const double median = n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
        std::printf("median Coin/volsg over %zu cases %.2f, lowest %.2f\n", n, median, s.front());
    }
    return ran;
}

} // namespace volsg::bench
