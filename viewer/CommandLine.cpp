#include "CommandLine.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>

#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>

namespace volsg::cli {

Arguments::Arguments(int argc, char** argv) : args_(argv + 1, argv + argc) {}

std::string Arguments::take() {
    return args_[next_++];
}

std::string Arguments::value(std::string_view option) {
    if (empty()) throw Error("option " + std::string(option) + " needs a value");
    return take();
}

int Arguments::intValue(std::string_view option, int min, int max) {
    const std::string text = value(option);
    int v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || v < min || v > max)
        throw Error("option " + std::string(option) + " expects a whole number from " +
                    std::to_string(min) + " to " + std::to_string(max) + ", not '" + text + "'");
    return v;
}

int runTool(const char* name, int argc, char** argv, const std::function<int(Arguments&)>& body) {
    try {
        Arguments args(argc, argv);
        return body(args);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", name, e.what());
        return 1;
    }
}

Options& Options::add(const Names& names, Action action) {
    for (const std::string& name : names.list)
        actions_.emplace_back(name, action);
    return *this;
}

Options& Options::flag(const Names& names, bool& target, bool value) {
    return add(names, [&target, value](Arguments&, const std::string&) { target = value; });
}

Options& Options::value(const Names& names, std::function<void(const std::string&)> set) {
    return add(names, [set = std::move(set)](Arguments& args, const std::string& option) {
        set(args.value(option));
    });
}

Options& Options::text(const Names& names, std::string& target) {
    return add(names, [&target](Arguments& args, const std::string& option) {
        target = args.value(option);
    });
}

Options& Options::integer(const Names& names, int& target, int min, int max, bool* given) {
    return add(names, [&target, min, max, given](Arguments& args, const std::string& option) {
        target = args.intValue(option, min, max);
        if (given) *given = true;
    });
}

Options& Options::size(const Names& names, int& width, int& height, bool* given) {
    return add(names, [&width, &height, given](Arguments& args, const std::string& option) {
        const glm::ivec2 s = parseSize(args.value(option));
        width = s.x;
        height = s.y;
        if (given) *given = true;
    });
}

Options& Options::color(const Names& names, glm::vec3& target) {
    return add(names, [&target](Arguments& args, const std::string& option) {
        target = parseColor(args.value(option));
    });
}

Options& Options::fraction(const Names& names, double& target) {
    return add(names, [&target](Arguments& args, const std::string& option) {
        target = parseFraction(args.value(option), option);
    });
}

bool Options::read(Arguments& args, const char* usage, const Operand& operand) const {
    while (!args.empty()) {
        const std::string a = args.take();
        if (a == "-h" || a == "--help") {
            std::fputs(usage, stdout);
            return false;
        }
        const auto found = std::find_if(actions_.begin(), actions_.end(),
                                        [&](const auto& entry) { return entry.first == a; });
        if (found != actions_.end())
            found->second(args, a);
        else if (!operand)
            throw Error("unknown argument '" + a + "'");
        else if (!a.empty() && a[0] == '-')
            throw Error("unknown option '" + a + "'");
        else
            operand(a);
    }
    return true;
}

Options::Operand sceneOperand(std::string& scene) {
    return [&scene](const std::string& a) {
        if (!scene.empty())
            throw Error("more than one scene file given ('" + scene + "', '" + a + "')");
        scene = a;
    };
}

int usageError(const char* usage) {
    std::fputs(usage, stderr);
    return 2;
}

namespace {

VoxelType parseVoxelType(const std::string& text) {
    std::string t;
    for (const char c : text)
        t += char(std::tolower(static_cast<unsigned char>(c)));
    if (t == "uchar" || t == "ubyte" || t == "uint8") return VoxelType::UByte;
    if (t == "ushort" || t == "uint16") return VoxelType::UShort;
    if (t == "short" || t == "int16") return VoxelType::Short;
    if (t == "float" || t == "float32") return VoxelType::Float;
    throw Error("--type expects uchar, ushort, short or float, not '" + text + "'");
}

double parseNumberWord(const std::string& text, std::string_view option) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v))
        throw Error("option " + std::string(option) + " expects numbers, not '" + text + "'");
    return v;
}

} // namespace

std::string withRawUsage(const char* usage) {
    std::string text = usage;
    const std::size_t at = text.find("%s");
    if (at != std::string::npos)
        text.replace(at, 2,
                     "  raw voxels: --dims X Y Z --type uchar|ushort|short|float\n"
                     "              [--spacing SX SY SZ] [--big-endian] [--header-skip BYTES]\n"
                     "              (plain or gzip files)\n");
    return text;
}

Options& Options::rawVolume(OpenFileOptions& open) {
    const auto layout = [&open]() -> RawVolumeLayout& {
        if (!open.raw) open.raw = RawVolumeLayout{};
        return *open.raw;
    };
    add("--dims", [layout](Arguments& args, const std::string& option) {
        glm::ivec3& d = layout().dimensions;
        for (int a = 0; a < 3; ++a)
            d[a] = args.intValue(option, 1, limits::maxVolumeDimension);
    });
    value("--type", [layout](const std::string& v) { layout().type = parseVoxelType(v); });
    add("--spacing", [layout](Arguments& args, const std::string& option) {
        glm::dvec3& s = layout().spacing;
        for (int a = 0; a < 3; ++a) {
            s[a] = parseNumberWord(args.value(option), option);
            if (!(s[a] > 0.0)) throw Error("option --spacing expects numbers > 0");
        }
    });
    add("--big-endian", [layout](Arguments&, const std::string&) { layout().bigEndian = true; });
    add("--header-skip", [layout](Arguments& args, const std::string& option) {
        layout().headerSkip = std::uint64_t(args.intValue(option, 0, 1 << 30));
    });
    return *this;
}

void checkRawLayout(const OpenFileOptions& open) {
    if (open.raw && open.raw->dimensions == glm::ivec3(0))
        throw Error("raw volume options need --dims X Y Z");
}

glm::ivec2 parseSize(const std::string& text) {
    const auto x = text.find('x');
    int w = 0, h = 0;
    bool ok = x != std::string::npos;
    if (ok) {
        auto r1 = std::from_chars(text.data(), text.data() + x, w);
        auto r2 = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
        ok = r1.ec == std::errc() && r1.ptr == text.data() + x && r2.ec == std::errc() &&
             r2.ptr == text.data() + text.size();
    }
    if (!ok || w < 1 || h < 1 || w > 16384 || h > 16384)
        throw Error("--size expects WxH with 1 <= W, H <= 16384, not '" + text + "'");
    return {w, h};
}

glm::vec3 parseColor(const std::string& text) {
    glm::vec3 c(0.0f);
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t end = i < 2 ? text.find(',', start) : text.size();
        if (end == std::string::npos) throw Error("--background expects R,G,B, not '" + text + "'");
        const std::string part = text.substr(start, end - start);
        char* stop = nullptr;
        const double v = std::strtod(part.c_str(), &stop);
        if (part.empty() || *stop != '\0' || !std::isfinite(v) || v < 0.0 || v > 1.0)
            throw Error("--background expects three numbers in [0,1] as R,G,B, not '" + text + "'");
        c[i] = float(v);
        start = end + 1;
    }
    return c;
}

double parseFraction(const std::string& text, std::string_view option) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(v > 0.0) || !(v <= 1.0))
        throw Error("option " + std::string(option) + " expects a number in (0, 1], not '" + text +
                    "'");
    return v;
}

std::string extensionOf(const std::string& path) {
    const auto slash = path.find_last_of('/');
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
    std::string ext = path.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return char(std::tolower(ch)); });
    return ext;
}

} // namespace volsg::cli
