// No glad here: the GL calls below are Mesa's own (OSMesaGetProcAddress), as Coin's are.
#include <GL/osmesa.h>

#include "CoinScene.h"

#include <chrono>
#include <cstring>

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoInteraction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodekits/SoNodeKit.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTransform.h>

#include <volsg/core/Error.h>

namespace volsg::bench {

namespace {

template <class F> F glFunction(const char* name) {
    auto f = reinterpret_cast<F>(OSMesaGetProcAddress(name));
    if (!f) throw volsg::Error(std::string("osmesa: no ") + name);
    return f;
}

} // namespace

void CoinScene::initCoin() {
    static bool done = false;
    if (done) return;
    done = true;
    SoDB::init();
    SoNodeKit::init();
    SoInteraction::init();
}

struct CoinScene::Impl {
    OSMesaContext context = nullptr;
    std::vector<unsigned char> buffer;
    int width = 0, height = 0;
    SoSeparator* root = nullptr;
    SoTransform* edited = nullptr;
    SbVec3f editedTranslation;
    SoGLRenderAction* render = nullptr;
};

CoinScene::CoinScene(const std::string& path, int width, int height)
    : impl_(std::make_unique<Impl>()) {
    initCoin();
    Impl& s = *impl_;
    s.width = width;
    s.height = height;
    s.buffer.assign(std::size_t(width) * std::size_t(height) * 4, 0);
    // A compatibility context (Coin draws with the fixed-function pipeline): RGBA, 24-bit depth.
    s.context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!s.context) throw volsg::Error("osmesa: OSMesaCreateContextExt failed");
    if (!OSMesaMakeCurrent(s.context, s.buffer.data(), GL_UNSIGNED_BYTE, width, height))
        throw volsg::Error("osmesa: OSMesaMakeCurrent failed");
    SoInput input;
    if (!input.openFile(path.c_str())) throw volsg::Error("Coin cannot open " + path);
    s.root = SoDB::readAll(&input);
    input.closeFile();
    if (!s.root) throw volsg::Error("Coin cannot read " + path);
    s.root->ref();

    SoSearchAction search;
    search.setType(SoTransform::getClassTypeId());
    search.setInterest(SoSearchAction::ALL);
    search.apply(s.root);
    const SoPathList& paths = search.getPaths();
    if (paths.getLength() > 0) {
        s.edited = static_cast<SoTransform*>(paths[paths.getLength() / 2]->getTail());
        s.editedTranslation = s.edited->translation.getValue();
    }
    s.render = new SoGLRenderAction(SbViewportRegion(short(width), short(height)));
}

CoinScene::~CoinScene() {
    Impl& s = *impl_;
    if (s.context)
        OSMesaMakeCurrent(s.context, s.buffer.data(), GL_UNSIGNED_BYTE, s.width, s.height);
    delete s.render; // frees Coin's GL caches while the context is current
    if (s.root) s.root->unref();
    if (s.context) {
        OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
        OSMesaDestroyContext(s.context);
    }
}

double CoinScene::frameMs() {
    Impl& s = *impl_;
    if (!OSMesaMakeCurrent(s.context, s.buffer.data(), GL_UNSIGNED_BYTE, s.width, s.height))
        throw volsg::Error("osmesa: OSMesaMakeCurrent failed");
    using ClearColor = void (*)(GLfloat, GLfloat, GLfloat, GLfloat);
    using Clear = void (*)(GLbitfield);
    using Enable = void (*)(GLenum);
    using Finish = void (*)();
    static const auto clearColor = glFunction<ClearColor>("glClearColor");
    static const auto clear = glFunction<Clear>("glClear");
    static const auto enable = glFunction<Enable>("glEnable");
    static const auto finish = glFunction<Finish>("glFinish");
    const auto t0 = std::chrono::steady_clock::now();
    clearColor(0.0f, 0.0f, 0.0f, 1.0f);
    clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    enable(GL_DEPTH_TEST);
    s.render->apply(s.root);
    finish();
    const auto t1 = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

bool CoinScene::editTransform(float offset) {
    Impl& s = *impl_;
    if (!s.edited) return false;
    s.edited->translation.setValue(s.editedTranslation + SbVec3f(offset, 0.0f, 0.0f));
    return true;
}

std::vector<unsigned char> CoinScene::pixels() const {
    const Impl& s = *impl_;
    const std::size_t row = std::size_t(s.width) * 4;
    std::vector<unsigned char> out(s.buffer.size());
    for (int y = 0; y < s.height; ++y)
        std::memcpy(out.data() + std::size_t(y) * row,
                    s.buffer.data() + std::size_t(s.height - 1 - y) * row, row);
    return out;
}

} // namespace volsg::bench
