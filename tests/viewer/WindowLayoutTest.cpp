// The viewer's window layout: the panel column and the views never overlap, the views tile the
// rest of the window exactly, and each view is inside the window, for window sizes from tiny
// to large, both layouts, panels on and off.
#include <doctest/doctest.h>

#include "view/WindowLayout.h"

using namespace volsg;

TEST_CASE("panels and views never overlap and the views fill the rest of the window") {
    for (const glm::ivec2 size : {glm::ivec2(1, 1), glm::ivec2(150, 90), glm::ivec2(401, 301),
                                  glm::ivec2(640, 400), glm::ivec2(800, 500), glm::ivec2(1280, 800),
                                  glm::ivec2(1281, 799), glm::ivec2(2560, 1440)})
        for (const bool panels : {false, true})
            for (const ViewLayout mode : {ViewLayout::Single, ViewLayout::Four}) {
                CAPTURE(size.x);
                CAPTURE(size.y);
                CAPTURE(panels);
                const WindowLayout l = layoutWindow(size, panels, mode);
                CHECK(l.viewCount == (mode == ViewLayout::Four ? 4 : 1));
                CHECK(l.panels.empty() == (!panels || size.x < 2));
                long long viewArea = 0;
                for (int v = 0; v < l.viewCount; ++v) {
                    const PixelRect& r = l.views[std::size_t(v)];
                    CAPTURE(v);
                    CHECK(!r.empty());
                    CHECK(!r.overlaps(l.panels));
                    CHECK(r.x >= 0);
                    CHECK(r.y >= 0);
                    if (size.x >= 4 && size.y >= 2) { // large enough for a pixel per view
                        CHECK(r.x + r.width <= size.x);
                        CHECK(r.y + r.height <= size.y);
                    }
                    for (int w = v + 1; w < l.viewCount; ++w)
                        CHECK(!r.overlaps(l.views[std::size_t(w)]));
                    viewArea += (long long)r.width * r.height;
                }
                if (size.x >= 4 && size.y >= 2) {
                    const long long panelArea = (long long)l.panels.width * l.panels.height;
                    CHECK(viewArea + panelArea == (long long)size.x * size.y);
                }
                if (!l.panels.empty()) { // the column runs down the right edge, full height
                    CHECK(l.panels.x + l.panels.width == size.x);
                    CHECK(l.panels.height == size.y);
                }
            }
}

TEST_CASE("the panel column leaves the views most of a large window") {
    CHECK(panelColumnWidth(1280) == 384);
    CHECK(panelColumnWidth(800) == 260);
    CHECK(panelColumnWidth(2560) == 420);
    CHECK(panelColumnWidth(300) == 150); // half of a narrow window
    const WindowLayout l = layoutWindow({1280, 800}, true, ViewLayout::Four);
    CHECK(l.views[0] == PixelRect{0, 0, 448, 400});     // 3D
    CHECK(l.views[3] == PixelRect{448, 0, 448, 400});   // axial
    CHECK(l.views[2] == PixelRect{0, 400, 448, 400});   // coronal
    CHECK(l.views[1] == PixelRect{448, 400, 448, 400}); // sagittal
    CHECK(l.panels == PixelRect{896, 0, 384, 800});
}
