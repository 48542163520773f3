#pragma once
// volsg's half of volsg-coin-compare: reading a model (binary included, when the reader can),
// writing it back, and rendering the framed copy. Each runs in a child process of its own.

#include <string>

#include <glm/glm.hpp>

#include "ImageCompare.h"

namespace volsg::coincompare {

/// volsg::readScene(model), then volsg::writeSceneToFile(writeBackPath). Throws volsg::Error
/// (or whatever the reader throws) when reading fails; a failed write is returned, not thrown.
/// Returns "" when both worked, else why the write failed (one line).
std::string readAndWriteBackWithVolsg(const std::string& model, const std::string& writeBackPath);

/// volsg reads `framedPath` and renders it with a volsg::Renderer (default options but size and
/// background) in volsg's own OSMesa core-profile context. Throws.
Image8 renderWithVolsg(const std::string& framedPath, int width, int height, glm::vec3 background);

} // namespace volsg::coincompare
