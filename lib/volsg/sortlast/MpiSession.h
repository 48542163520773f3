#pragma once
// MPI_Init and MPI_Finalize as a scope (built only with MPI: volsg_sortlast).

namespace volsg {

/// Initialises MPI (single-threaded use) for its lifetime and finalises it on destruction.
class MpiSession {
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }

private:
    int rank_ = 0;
    int size_ = 1;
};

} // namespace volsg
