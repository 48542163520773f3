#include <volsg/sortlast/PremultipliedOver.h>

namespace volsg {

void compositeOver(const float* front, float* back, std::size_t pixels) {
    for (std::size_t i = 0; i < 4 * pixels; i += 4) {
        const float keep = 1.0f - front[i + 3];
        back[i + 0] = front[i + 0] + keep * back[i + 0];
        back[i + 1] = front[i + 1] + keep * back[i + 1];
        back[i + 2] = front[i + 2] + keep * back[i + 2];
        back[i + 3] = front[i + 3] + keep * back[i + 3];
    }
}

} // namespace volsg
