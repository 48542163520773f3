#include <volsg/sortlast/MpiLaunch.h>

#include <cstdlib>
#include <initializer_list>

namespace volsg {

int mpiLaunchSize() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE"})
        if (const char* value = std::getenv(name)) {
            const int size = std::atoi(value);
            if (size > 0) return size;
        }
    return 0;
}

} // namespace volsg
