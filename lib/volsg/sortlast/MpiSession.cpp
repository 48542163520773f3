#include <volsg/sortlast/MpiSession.h>

#include <mpi.h>

namespace volsg {

MpiSession::MpiSession(int& argc, char**& argv) {
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
    MPI_Finalize();
}

} // namespace volsg
