// No glad here: the GL calls below are Mesa's own (OSMesaGetProcAddress), as Coin's are.
#include <GL/osmesa.h>

#include "CoinSide.h"

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoInteraction.h>
#include <Inventor/SoOutput.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoError.h>
#include <Inventor/errors/SoMemoryError.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodekits/SoBaseKit.h>
#include <Inventor/nodekits/SoNodeKit.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoFile.h>
#include <Inventor/nodes/SoLight.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <volsg/core/Error.h>

#include "ModelReport.h"

namespace volsg::coincompare {

namespace {

std::vector<std::string> messages;

void collect(const SoError* error, void*) {
    messages.push_back(oneLine(error->getDebugString().getString(), 1000));
}

std::vector<std::string> takeMessages() {
    std::vector<std::string> out;
    out.swap(messages);
    return out;
}

void initCoin() {
    static bool done = false;
    if (done) return;
    done = true;
    SoDB::init();
    SoNodeKit::init();
    SoInteraction::init();
    SoError::setHandlerCallback(collect, nullptr);
    SoDebugError::setHandlerCallback(collect, nullptr);
    SoReadError::setHandlerCallback(collect, nullptr);
    SoMemoryError::setHandlerCallback(collect, nullptr);
    SoBaseKit::setSearchingChildren(TRUE); // lights and cameras inside node kits count too
}

/// SoDB::readAll of a file; nullptr when Coin cannot open or read it (its messages say why).
SoSeparator* readFile(const std::string& path) {
    SoInput input;
    if (!input.openFile(path.c_str())) return nullptr;
    SoSeparator* root = SoDB::readAll(&input);
    input.closeFile();
    return root;
}

std::string firstMessageOr(const std::vector<std::string>& list, const std::string& otherwise) {
    return list.empty() ? otherwise : list.front();
}

/// The first node of `type` a default search finds (Switches honoured, as rendering does).
bool contains(SoNode* root, SoType type) {
    SoSearchAction search;
    search.setType(type, TRUE);
    search.setInterest(SoSearchAction::FIRST);
    search.apply(root);
    return search.getPath() != nullptr;
}

/// Top-level File nodes (not inside another File, whose children are not written) get the
/// absolute path of the file Coin read for them.
int makeFileNamesAbsolute(SoNode* root) {
    SoSearchAction search;
    search.setType(SoFile::getClassTypeId(), TRUE);
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(root);
    std::vector<SoFile*> files;
    const SoPathList& paths = search.getPaths();
    for (int i = 0; i < paths.getLength(); ++i) {
        const SoPath* path = paths[i];
        bool nested = false;
        for (int k = 0; k + 1 < path->getLength(); ++k)
            if (path->getNode(k)->isOfType(SoFile::getClassTypeId())) nested = true;
        if (!nested) files.push_back(static_cast<SoFile*>(path->getTail()));
    }
    int changed = 0;
    for (SoFile* file : files) {
        const std::string full = file->getFullName().getString();
        if (full.empty()) continue; // Coin did not find it either: leave the name as it is
        std::error_code ec;
        const std::string absolute =
            std::filesystem::absolute(full, ec).lexically_normal().string();
        if (ec || absolute == file->name.getValue().getString()) continue;
        file->ref();
        file->name.setValue(absolute.c_str()); // Coin reads the file again, by this name
        file->unrefNoDelete();
        ++changed;
    }
    return changed;
}

/// Mesa's GL entry points for the few calls made here.
template <class F> F glFunction(const char* name) {
    auto f = reinterpret_cast<F>(OSMesaGetProcAddress(name));
    if (!f) throw volsg::Error(std::string("osmesa: no ") + name);
    return f;
}

} // namespace

Framing frameWithCoin(const std::string& model, const std::string& framedPath, int width,
                      int height, FramingView view) {
    initCoin();
    Framing framing;
    SoSeparator* scene = readFile(model);
    framing.readMessages = takeMessages();
    if (!scene)
        throw volsg::Error("Coin cannot read it: " +
                           firstMessageOr(framing.readMessages, "SoDB::readAll failed"));
    scene->ref();
    framing.filesMadeAbsolute = makeFileNamesAbsolute(scene);

    SoSeparator* root = new SoSeparator;
    root->ref();
    // The view direction (and the headlight along it): Inventor's default -Z, or from above
    // front right, where no model of the samples is seen edge-on.
    SbVec3f viewDirection(0.0f, 0.0f, -1.0f);
    if (view == FramingView::Oblique) {
        const float azimuth = 30.0f * float(M_PI) / 180.0f,
                    elevation = 25.0f * float(M_PI) / 180.0f;
        viewDirection = -SbVec3f(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                                 std::cos(azimuth) * std::cos(elevation));
    }
    if (!contains(scene, SoCamera::getClassTypeId())) {
        auto* camera = new SoPerspectiveCamera;
        root->addChild(camera);
        if (view == FramingView::Oblique) {
            camera->position.setValue(-viewDirection);
            camera->pointAt(SbVec3f(0.0f, 0.0f, 0.0f), SbVec3f(0.0f, 1.0f, 0.0f));
        }
        const SbViewportRegion viewport{short(width), short(height)};
        camera->viewAll(scene, viewport); // keeps the orientation, moves the camera
        framing.addedCamera = true;
    }
    if (!contains(scene, SoLight::getClassTypeId())) {
        auto* headlight = new SoDirectionalLight;
        headlight->direction.setValue(viewDirection);
        root->addChild(headlight);
        framing.addedLight = true;
    }
    root->addChild(scene);

    SoOutput output;
    if (!output.openFile(framedPath.c_str()))
        throw volsg::Error("Coin cannot write " + framedPath + ": " +
                           firstMessageOr(takeMessages(), "SoOutput::openFile failed"));
    SoWriteAction write(&output);
    write.apply(root);
    output.closeFile();
    const std::vector<std::string> writeMessages = takeMessages();
    framing.readMessages.insert(framing.readMessages.end(), writeMessages.begin(),
                                writeMessages.end());
    return framing;
}

CoinRender renderWithCoin(const std::string& framedPath, int width, int height,
                          glm::vec3 background) {
    // A compatibility context (Coin draws with the fixed-function pipeline): RGBA, 24-bit depth.
    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!context) throw volsg::Error("osmesa: OSMesaCreateContextExt failed");
    std::vector<unsigned char> buffer(std::size_t(width) * std::size_t(height) * 4, 0);
    if (!OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, width, height))
        throw volsg::Error("osmesa: OSMesaMakeCurrent failed");

    initCoin();
    SoSeparator* root = readFile(framedPath);
    CoinRender result;
    result.messages = takeMessages();
    if (!root)
        throw volsg::Error("Coin cannot read the framed copy: " +
                           firstMessageOr(result.messages, "SoDB::readAll failed"));
    root->ref();

    using ClearColor = void (*)(GLfloat, GLfloat, GLfloat, GLfloat);
    using Clear = void (*)(GLbitfield);
    using Enable = void (*)(GLenum);
    using Finish = void (*)();
    glFunction<ClearColor>("glClearColor")(background.r, background.g, background.b, 1.0f);
    glFunction<Clear>("glClear")(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glFunction<Finish>("glFinish")();
    result.background = {buffer[0], buffer[1], buffer[2]};
    glFunction<Enable>("glEnable")(GL_DEPTH_TEST);

    const SbViewportRegion viewport{short(width), short(height)};
    SoGLRenderAction render(viewport);
    render.apply(root);
    glFunction<Finish>("glFinish")();
    for (std::string& m : takeMessages())
        // Coin looks for a GLX context it never gets (OSMesa is current): not about the model.
        if (m.find("glxglue") == std::string::npos) result.messages.push_back(std::move(m));
    result.image = fromBottomUpRgba(buffer.data(), width, height);
    return result;
}

std::vector<std::string> coinReadMessages(const std::string& path,
                                          const std::string& extraDirectory, bool& readOk) {
    initCoin();
    if (!extraDirectory.empty()) SoInput::addDirectoryFirst(extraDirectory.c_str());
    SoSeparator* root = readFile(path);
    readOk = root != nullptr;
    if (root) {
        root->ref();
        root->unref();
    }
    return takeMessages();
}

} // namespace volsg::coincompare
