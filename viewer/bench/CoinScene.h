#pragma once
// Coin3D's side of `volsg-bench --suite coin`: a scene file drawn by SoGLRenderAction in an
// OSMesa compatibility context of its own, timed as a Coin application's frame (clear,
// traversal, glFinish). No Coin header here, so the suite's other files need none.

#include <memory>
#include <string>
#include <vector>

namespace volsg::bench {

class CoinScene {
public:
    /// Coin reads `path` and makes an OSMesa RGBA context with a 24-bit depth buffer
    /// (width x height). Throws volsg::Error when Coin cannot read the file.
    CoinScene(const std::string& path, int width, int height);
    ~CoinScene();
    CoinScene(const CoinScene&) = delete;
    CoinScene& operator=(const CoinScene&) = delete;

    /// Makes the context current, then clears, applies one SoGLRenderAction (Coin's defaults:
    /// separators cache on AUTO) and waits for glFinish. Returns the wall-clock milliseconds of
    /// those three steps.
    double frameMs();
    /// Moves the Transform in the middle of the file's Transforms (in traversal order) by
    /// `offset` along x from its read value; false when the scene has none.
    bool editTransform(float offset);
    /// The last frame, RGBA bytes, row 0 at the top.
    std::vector<unsigned char> pixels() const;

    /// Coin's SoDB::init and friends, once per process.
    static void initCoin();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace volsg::bench
