#include <volsg/shearwarp/SimdLevel.h>

namespace volsg {

bool simdLevelAvailable(SimdLevel level) {
    if (level == SimdLevel::Scalar) return true;
#if defined(__x86_64__) || defined(__i386__)
    static const bool avx2 = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return avx2;
#else
    return false;
#endif
}

SimdLevel bestSimdLevel() {
    return simdLevelAvailable(SimdLevel::Avx2) ? SimdLevel::Avx2 : SimdLevel::Scalar;
}

} // namespace volsg
