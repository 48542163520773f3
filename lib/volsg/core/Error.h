#pragma once
// The one error type: where (file, line, column) and what.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace volsg {

/// Thrown for bad input and failed operations. `what()` is one line:
/// "file:line:column: message" (parts that are unknown are left out), of at most
/// kMaxMessageLength characters (a longer message is cut in the middle, so both its start and
/// its end show).
class Error : public std::runtime_error {
public:
    static constexpr std::size_t kMaxMessageLength = 1000;

    explicit Error(std::string message, std::string file = {}, int line = 0, int column = 0);

    const std::string& message() const noexcept { return message_; }
    const std::string& file() const noexcept { return file_; }
    int line() const noexcept { return line_; }
    int column() const noexcept { return column_; }

    /// This error happened while a traversal was at a node read from a scene file: it already
    /// names that file and node (Action::traverse adds them once, at the innermost node).
    bool namesSceneNode() const noexcept { return namesSceneNode_; }
    /// The same error, said of the node read at file:line:column (`node` names it: "Volume",
    /// "VolumeData 'CT'"): "file:line:column: node: <what this error said>".
    static Error atSceneNode(const std::exception& inner, const std::string& node,
                             const std::string& file, int line, int column);

private:
    std::string message_;
    std::string file_;
    int line_ = 0;
    int column_ = 0;
    bool namesSceneNode_ = false;
};

} // namespace volsg
