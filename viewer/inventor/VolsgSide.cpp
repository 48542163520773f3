#include "VolsgSide.h"

#include <exception>

#include <volsg/context/Context.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/render/Renderer.h>

#include "ModelReport.h"

namespace volsg::coincompare {

std::string readAndWriteBackWithVolsg(const std::string& model, const std::string& writeBackPath) {
    volsg::ref_ptr<volsg::Node> root = volsg::readScene(model);
    try {
        volsg::writeSceneToFile(writeBackPath, *root);
    } catch (const std::exception& e) {
        return oneLine(std::string("volsg cannot write it back: ") + e.what());
    }
    return {};
}

Image8 renderWithVolsg(const std::string& framedPath, int width, int height, glm::vec3 background) {
    volsg::ref_ptr<volsg::Node> root = volsg::readScene(framedPath);
    auto context = volsg::Context::createOffscreen(volsg::Backend::OSMesa);
    Image8 image;
    {
        volsg::Renderer renderer; // gone before the context
        volsg::RenderOptions options;
        options.width = width;
        options.height = height;
        options.background = background;
        image = fromVolsg(renderer.render(*root, options));
    }
    return image;
}

} // namespace volsg::coincompare
