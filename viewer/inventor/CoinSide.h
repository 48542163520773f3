#pragma once
// Coin3D's half of volsg-coin-compare: reading a model, framing it (camera, headlight), writing
// the framed copy, rendering it with SoGLRenderAction into an OSMesa compatibility context, and
// reading a file while counting every message Coin posts. Each function runs in a child process
// of its own (ChildProcess.h), so Coin's global state is fresh every time.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "ImageCompare.h"

namespace volsg::coincompare {

/// What framing a model did.
struct Framing {
    bool addedCamera = false;  ///< false: the scene has a camera of its own, which is used
    bool addedLight = false;   ///< the headlight; false: the scene has a light of its own
    int filesMadeAbsolute = 0; ///< File nodes whose name now is the absolute path Coin found
    std::vector<std::string> readMessages; ///< what Coin said while reading the original
};

/// Where the framing camera looks from.
enum class FramingView {
    Front,  ///< along -Z, as Inventor's viewers open a file
    Oblique ///< from above front right: 30 degrees azimuth, 25 degrees elevation
};

/// Coin reads `model` and writes `framedPath`, an ASCII copy with root = Separator {
/// PerspectiveCamera (looking along `view`, then viewAll on the scene for a width x height
/// viewport), DirectionalLight (a headlight: the camera's view direction, 0 0 -1 for Front; only
/// when the scene has no SoLight of its own), the scene }. A scene with a camera of its own
/// keeps it and gets none. Top-level File nodes get the absolute name of the file Coin read, so
/// the copy reads the same from another folder. Throws volsg::Error when Coin cannot read the
/// model or write the copy.
Framing frameWithCoin(const std::string& model, const std::string& framedPath, int width,
                      int height, FramingView view);

struct CoinRender {
    Image8 image;
    Rgb8 background{}; ///< the cleared colour as the buffer holds it
    std::vector<std::string> messages;
};

/// Coin reads `framedPath` and draws it with SoGLRenderAction (default settings) into an OSMesa
/// RGBA context with a 24-bit depth buffer, cleared to `background`. Throws volsg::Error.
CoinRender renderWithCoin(const std::string& framedPath, int width, int height,
                          glm::vec3 background);

/// Coin reads `path` with `extraDirectory` first in its search path (where relative file names
/// of the original resolve). Returns every message Coin posted (SoError and subclasses: read
/// errors, debug warnings); `readOk` says whether SoDB::readAll returned a graph.
std::vector<std::string> coinReadMessages(const std::string& path,
                                          const std::string& extraDirectory, bool& readOk);

} // namespace volsg::coincompare
