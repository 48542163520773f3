// File: Inventor's SoFile. The included files are read without recursion: a File met while an
// included file is being parsed queues itself, and the File that started the include reads the
// queue after that parse, so a chain of includes of any length costs no stack. Each included
// file is parsed on a thread of its own, so its nesting has a whole stack to itself, as the
// scene file's own has, whatever the nesting depth of the File that names it. Every include
// carries the chain of files that led to it, so a file that includes itself (directly or
// through others) is refused; the nodes of all the files one read brings in count together
// against limits::maxSceneNodes.
#include <volsg/nodes/File.h>

#include <deque>
#include <exception>
#include <filesystem>
#include <thread>
#include <unordered_set>
#include <utility>
#include <vector>

#include <volsg/actions/Action.h>
#include <volsg/core/Limits.h>
#include <volsg/io/BinaryInput.h>
#include <volsg/io/ReadContext.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/Tokenizer.h>

namespace volsg {

void FileNameField::setValue(std::string v) {
    value_ = std::move(v);
    line_ = column_ = 0;
    changed();
}

void FileNameField::read(FieldInput& in) {
    if (BinaryInput* binary = in.binary()) { // a binary file has no lines to point at
        setValue(StringTraits::readBinary(*binary));
        return;
    }
    const Token& t = in.tokens().peek();
    const int line = t.line, column = t.column;
    setValue(StringTraits::read(in.tokens()));
    line_ = line;
    column_ = column;
}

void FileNameField::write(FieldOutput& out) const {
    StringTraits::write(out.stream(), value_);
}

bool FileNameField::equals(const Field& other) const {
    const auto* o = dynamic_cast<const FileNameField*>(&other);
    return o && o->value_ == value_;
}

void FileNameField::copyFrom(const Field& other) {
    const auto* o = dynamic_cast<const FileNameField*>(&other);
    if (!o)
        throw Error(std::string("cannot copy a ") + other.typeName() + " field into File's " +
                    name());
    value_ = o->value_;
    line_ = o->line_;
    column_ = o->column_;
    changed();
}

namespace {

/// One file of an include chain: as named (for messages) and canonical (to compare).
struct Included {
    std::string shown, canonical;
};
using Chain = std::vector<Included>;

struct Pending {
    ref_ptr<File> file;
    Chain chain; ///< the files being read when the File was met, outermost first
};

/// Set on the thread that parses an included file: the Files met there queue themselves.
struct NestedParse {
    std::vector<Pending>* queue = nullptr;
    const Chain* chain = nullptr;
};
thread_local NestedParse nested;

/// The read of a scene file that is going on on this thread, as its File nodes see it: the
/// nodes of every file its File nodes include count against one budget. Its File nodes come in
/// the order of their names in the text, so a File whose name is not after the last one seen
/// (or that has another ReadContext or file name) starts a new read.
struct TopRead {
    const ReadContext* context = nullptr; ///< only compared, never used
    std::string fileName;
    std::pair<int, int> position{0, 0};
    std::size_t nodes = 0;
};
thread_local TopRead topRead;

bool namesAFile(const std::string& name) {
    return !name.empty() && name != File::undefinedName;
}

Chain chainOf(const std::string& sceneFile) {
    std::error_code ec;
    if (sceneFile.empty() || !std::filesystem::is_regular_file(sceneFile, ec)) return {};
    const std::filesystem::path canonical = std::filesystem::canonical(sceneFile, ec);
    if (ec) return {};
    return {{sceneFile, canonical.string()}};
}

/// Nodes reachable from `root` through children and node fields, each once (USE shares).
std::size_t countNodes(Node& root) {
    std::unordered_set<const Node*> seen;
    std::vector<Node*> stack{&root};
    while (!stack.empty()) {
        Node* node = stack.back();
        stack.pop_back();
        if (!node || !seen.insert(node).second) continue;
        if (auto* children = node->children())
            for (const auto& child : *children)
                stack.push_back(child.get());
        for (std::size_t i = 0, n = node->fieldCount(); i < n; ++i) {
            Field* f = node->fieldAt(i);
            if (auto* sf = dynamic_cast<SFNode*>(f)) stack.push_back(sf->getValue());
            if (auto* mf = dynamic_cast<MFNode*>(f))
                for (const auto& v : mf->getValues())
                    stack.push_back(v.get());
        }
    }
    return seen.size();
}

/// Reads an included file on a thread of its own (a fresh stack: the reader's nesting limit is
/// sized for one), with the Files met in it queued into `found`.
ref_ptr<Node> parseIncluded(const std::string& path, std::vector<Pending>& found,
                            const Chain& chain) {
    ref_ptr<Node> graph;
    std::exception_ptr failure;
    std::thread reader([&] {
        nested = {&found, &chain};
        try {
            graph = readScene(path);
        } catch (...) {
            failure = std::current_exception();
        }
        nested = {};
    });
    reader.join();
    if (failure) std::rethrow_exception(failure);
    return graph;
}

std::string chainText(const Chain& chain, const std::string& last) {
    std::string s;
    for (const Included& i : chain)
        s += i.shown + " -> ";
    return s + last;
}

} // namespace

/// Reads what File nodes name, breadth first, with the checks of the file comment.
struct FileIncluder {
    static Error errorAt(const File& file, const std::string& message) {
        return Error("File \"" + file.name() + "\": " + message, file.sceneFile_, file.name.line(),
                     file.name.column());
    }

    static std::string place(const File& file) {
        std::string s = file.sceneFile_.empty() ? std::string("<code>") : file.sceneFile_;
        if (file.name.line() > 0)
            s += ":" + std::to_string(file.name.line()) + ":" + std::to_string(file.name.column());
        return s;
    }

    static void include(File& root, Chain chain, std::size_t& nodes) {
        std::deque<Pending> work;
        work.push_back({ref_ptr<File>(&root), std::move(chain)});
        while (!work.empty()) {
            Pending p = std::move(work.front());
            work.pop_front();
            File& file = *p.file;
            // Lexically normal ("sub/../a.iv" is "a.iv"), so messages name files plainly.
            const std::string path =
                std::filesystem::path(
                    ReadContext{file.sceneFile_, file.directory_}.resolve(file.name()))
                    .lexically_normal()
                    .string();

            std::error_code ec;
            const auto status = std::filesystem::status(path, ec);
            if (ec || status.type() != std::filesystem::file_type::regular) {
                const std::string why = ec ? ec.message()
                                           : (status.type() == std::filesystem::file_type::not_found
                                                  ? std::string("No such file or directory")
                                                  : std::string("not a regular file"));
                file.readError_ = errorAt(file, "cannot read '" + path + "': " + why);
                continue;
            }
            const std::filesystem::path canonical = std::filesystem::canonical(path, ec);
            const std::string key =
                ec ? std::filesystem::absolute(path).string() : canonical.string();
            for (const Included& i : p.chain)
                if (i.canonical == key)
                    throw errorAt(file, "'" + path +
                                            "' is already being read: a file cannot include "
                                            "itself (" +
                                            chainText(p.chain, path) + ")");
            if (p.chain.size() >= std::size_t(File::maxIncludeDepth))
                throw errorAt(file, "files include one another more than " +
                                        std::to_string(File::maxIncludeDepth) + " levels deep");

            Chain inner = p.chain;
            inner.push_back({path, key});
            std::vector<Pending> found;
            ref_ptr<Node> graph;
            try {
                graph = parseIncluded(path, found, inner);
            } catch (const Error& e) {
                // Errors in an included file name that file; say which File included it.
                if (e.file() != path) throw;
                throw Error(e.message() + " (in the file included by the File at " + place(file) +
                                ")",
                            e.file(), e.line(), e.column());
            }
            nodes += countNodes(*graph);
            if (nodes > limits::maxSceneNodes)
                throw errorAt(file, "the files included by File nodes have more than " +
                                        std::to_string(limits::maxSceneNodes) + " nodes together");
            file.contents_ = std::move(graph);
            for (Pending& q : found)
                work.push_back(std::move(q));
        }
    }
};

void File::readDone(const ReadContext& context) {
    directory_ = context.directory;
    sceneFile_ = context.fileName;
    readVersion_ = version();
    contents_ = nullptr;
    readError_.reset();
    if (!namesAFile(name())) return;
    if (nested.queue) { // inside an included file: the File that included it reads this one
        nested.queue->push_back({ref_ptr<File>(this), *nested.chain});
        return;
    }
    const std::pair<int, int> position{name.line(), name.column()};
    if (topRead.context != &context || topRead.fileName != context.fileName ||
        !(topRead.position < position))
        topRead = TopRead{&context, context.fileName, position, 0};
    topRead.position = position;
    FileIncluder::include(*this, chainOf(context.fileName), topRead.nodes);
}

void File::update() {
    if (readVersion_ == version()) return;
    readVersion_ = version();
    contents_ = nullptr;
    readError_.reset();
    if (!namesAFile(name())) return;
    try {
        std::size_t nodes = 0;
        FileIncluder::include(*this, chainOf(sceneFile_), nodes);
    } catch (const Error& e) {
        contents_ = nullptr;
        readError_ = e;
    }
}

void File::doAction(Action& action) {
    update();
    if (contents_) action.traverse(*contents_);
}

} // namespace volsg
