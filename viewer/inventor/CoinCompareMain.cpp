// volsg-coin-compare: how volsg reads, renders and writes back real Inventor files, measured
// against Coin3D. For each model: volsg reads the original; Coin frames it (camera, headlight)
// and writes the framed copy; Coin and volsg each render that copy; the images are compared
// (silhouette IoU, colour difference); Coin reads volsg's write-back of the original. Every
// step runs in a child process with a deadline. viewer/inventor/README.md.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../CommandLine.h"
#include <volsg/core/Error.h>

#include "ChildProcess.h"
#include "CoinSide.h"
#include "ImageCompare.h"
#include "ModelReport.h"
#include "VolsgSide.h"

namespace fs = std::filesystem;
using namespace volsg::coincompare;

namespace {

const char* defaultModels = "/usr/share/inventor/data/models";

const char* usage =
    "usage: volsg-coin-compare [MODEL.iv|FOLDER ...] [--out DIR] [--markdown FILE]\n"
    "                          [--view oblique|front] [--size WxH] [--background R,G,B]\n"
    "                          [--jobs N] [--timeout SECONDS]\n"
    "                          [--require-agree FRACTION] [--expect-models N] [--verify]\n"
    "  MODEL/FOLDER      models to compare; folders are searched for *.iv (default\n"
    "                    /usr/share/inventor/data/models, Debian's inventor-data)\n"
    "  --out DIR         where the framed copies, write-backs and images go, and results.tsv\n"
    "                    (default coin-compare)\n"
    "  --markdown FILE   also write the table as Markdown, with a 'why it differs' column\n"
    "  --view            where the framing camera looks from: oblique (default; from above\n"
    "                    front right, 30 degrees azimuth, 25 elevation) or front (along -Z, as\n"
    "                    Inventor's viewers open a file; flat models are then seen edge-on)\n"
    "  --size WxH        render size (default 256x256)\n"
    "  --background R,G,B  the background both renderers clear to (default 0,0,0)\n"
    "  --jobs N          models compared at once (default 1)\n"
    "  --timeout SECONDS  the limit of each step of a model (default 60)\n"
    "  --require-agree FRACTION  exit with status 3 unless at least this fraction of the models\n"
    "                    agree (IoU >= 0.9 and colour difference <= 0.08)\n"
    "  --expect-models N exit with status 4 unless exactly N models were compared\n"
    "  --verify          check the tool itself (status 4 on failure): Coin rendered and framed\n"
    "                    every model, the numbers of every row match the PNGs written, every\n"
    "                    message is one bounded line, the Markdown table has every row\n";

struct Settings {
    std::vector<std::string> inputs;
    std::string out = "coin-compare";
    std::string markdown;
    int width = 256;
    int height = 256;
    glm::vec3 background{0.0f};
    int jobs = 1;
    double timeout = 60.0;
    double requireAgree = -1.0;
    int expectModels = -1;
    bool verify = false;
    FramingView view = FramingView::Oblique;
};

struct Model {
    std::string path;  ///< as opened
    std::string shown; ///< relative to the folder it was found in, or as given
    std::string stem;  ///< its files in the output folder: OUT/stem.*
};

struct ModelFiles {
    std::string framed, writeBack, coinPng, volsgPng, sideBySide;
};

ModelFiles filesOf(const Settings& s, const Model& m) {
    const std::string base = (fs::path(s.out) / m.stem).string();
    return {base + ".framed.iv", base + ".volsg.iv", base + ".coin.png", base + ".volsg.png",
            base + ".png"};
}

double parseNumber(const std::string& text, const std::string& option, double min, double max) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(v >= min) || !(v <= max))
        throw volsg::Error(option + " wants a number in [" + std::to_string(min) + ", " +
                           std::to_string(max) + "], got '" + text + "'");
    return v;
}

bool isIvFile(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return c | 0x20; });
    return ext == ".iv";
}

std::vector<Model> findModels(const std::vector<std::string>& inputs) {
    std::vector<Model> models;
    for (const std::string& input : inputs) {
        std::error_code ec;
        if (fs::is_directory(input, ec)) {
            std::vector<Model> found;
            for (const auto& entry : fs::recursive_directory_iterator(input, ec)) {
                if (!entry.is_regular_file() || !isIvFile(entry.path())) continue;
                found.push_back({entry.path().string(),
                                 fs::relative(entry.path(), input).generic_string(),
                                 {}});
            }
            if (ec) throw volsg::Error("cannot list " + input + ": " + ec.message());
            std::sort(found.begin(), found.end(),
                      [](const Model& a, const Model& b) { return a.shown < b.shown; });
            models.insert(models.end(), found.begin(), found.end());
        } else if (fs::is_regular_file(input, ec)) {
            // Shown relative to the sample models' folder when it is one of them.
            const fs::path rel = fs::weakly_canonical(input, ec).lexically_relative(
                fs::weakly_canonical(defaultModels, ec));
            const bool sample = !ec && !rel.empty() && *rel.begin() != "..";
            models.push_back({input,
                              sample ? rel.generic_string()
                                     : fs::path(input).lexically_normal().generic_string(),
                              {}});
        } else {
            throw volsg::Error("no such file or folder: " + input);
        }
    }
    std::map<std::string, int> used;
    for (Model& m : models) {
        std::string stem = m.shown;
        if (isIvFile(stem)) stem.resize(stem.size() - 3);
        std::string safe;
        for (const char c : stem)
            safe += c == '/'                ? std::string("__")
                    : c == '\\' || c == ':' ? std::string("_")
                                            : std::string(1, c);
        stem = safe;
        while (!stem.empty() && (stem[0] == '.' || stem[0] == '_'))
            stem.erase(0, 1); // "../x" must not leave the output folder
        if (stem.empty()) stem = "model";
        const int n = ++used[stem];
        m.stem = n == 1 ? stem : stem + "~" + std::to_string(n);
    }
    return models;
}

void replaceAll(std::string& text, const std::string& from, const std::string& to) {
    if (from.empty()) return;
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
}

/// The messages a step reported (messageFields) as "first (+N more)", "" when none.
std::string messageSummary(const Fields& f) {
    const auto count = f.find("messages");
    const auto first = f.find("first");
    if (count == f.end() || first == f.end()) return {};
    const int n = std::atoi(count->second.c_str());
    if (n <= 0) return {};
    return first->second + (n > 1 ? " (+" + std::to_string(n - 1) + " more)" : "");
}

Fields messageFields(const std::vector<std::string>& messages) {
    return {{"messages", std::to_string(messages.size())},
            {"first", messages.empty() ? std::string() : messages.front()}};
}

Rgb8 parseRgb(const std::string& text) {
    int r = 0, g = 0, b = 0;
    if (std::sscanf(text.c_str(), "%d,%d,%d", &r, &g, &b) != 3)
        throw volsg::Error("bad colour '" + text + "'");
    return {std::uint8_t(r), std::uint8_t(g), std::uint8_t(b)};
}

/// Everything about one model; runs in a worker process, each step in a child of its own.
ModelRow processModel(const Settings& s, const Model& m) {
    ModelRow row;
    row.model = m.shown;
    row.header = headerKind(m.path);
    const ModelFiles files = filesOf(s, m);
    for (const std::string& f :
         {files.framed, files.writeBack, files.coinPng, files.volsgPng, files.sideBySide}) {
        std::error_code ec;
        fs::remove(f, ec); // nothing of an earlier run may pass for this one's
    }
    const std::string outPrefix = (fs::path(s.out) / "").string();
    auto shorten = [&](std::string text) {
        replaceAll(text, m.path, m.shown);
        replaceAll(text, outPrefix, "");
        return oneLine(text);
    };
    std::vector<std::string> notes;

    // 1. volsg reads the original and writes it back.
    std::string writeProblem;
    const ChildResult read =
        runInChild([&] { return readAndWriteBackWithVolsg(m.path, files.writeBack); }, s.timeout);
    if (read.ok) {
        row.readOk = true;
        writeProblem = shorten(read.output);
    } else {
        row.readError = shorten(read.problem);
    }

    // 2. Coin frames the original and writes the framed copy.
    const ChildResult frame = runInChild(
        [&] {
            const Framing f = frameWithCoin(m.path, files.framed, s.width, s.height, s.view);
            Fields fields = messageFields(f.readMessages);
            fields["camera"] = f.addedCamera ? "1" : "0";
            fields["light"] = f.addedLight ? "1" : "0";
            fields["files"] = std::to_string(f.filesMadeAbsolute);
            return encodeFields(fields);
        },
        s.timeout);
    const bool framed = frame.ok;
    if (!framed) {
        notes.push_back("Coin framing: " + shorten(frame.problem));
    } else {
        const Fields f = decodeFields(frame.output);
        const std::string messages = messageSummary(f);
        if (!messages.empty()) notes.push_back("Coin reading the original: " + shorten(messages));
        if (f.count("camera") && f.at("camera") == "0")
            notes.push_back("rendered through the scene's own camera");
        std::ifstream in(files.framed, std::ios::binary);
        const std::string text{std::istreambuf_iterator<char>(in),
                               std::istreambuf_iterator<char>()};
        std::string lacking;
        for (const std::string& type : typesVolsgLacks(nodeTypeNames(text)))
            lacking += (lacking.empty() ? "" : " ") + type;
        row.missingTypes = lacking;
    }

    // 3. Coin renders the framed copy.
    Rgb8 coinBackground = toRgb8(s.background);
    if (framed) {
        const ChildResult coin = runInChild(
            [&] {
                const CoinRender r = renderWithCoin(files.framed, s.width, s.height, s.background);
                writePng8(files.coinPng, r.image);
                Fields fields = messageFields(r.messages);
                fields["background"] = std::to_string(r.background[0]) + "," +
                                       std::to_string(r.background[1]) + "," +
                                       std::to_string(r.background[2]);
                return encodeFields(fields);
            },
            s.timeout);
        if (coin.ok) {
            row.coinRendered = true;
            const Fields f = decodeFields(coin.output);
            coinBackground = parseRgb(f.at("background"));
            row.coinBackground = coinBackground;
            const std::string messages = messageSummary(f);
            if (!messages.empty()) notes.push_back("Coin rendering: " + shorten(messages));
        } else {
            notes.push_back("Coin render: " + shorten(coin.problem));
        }
    }

    // 4. volsg renders the framed copy.
    const Rgb8 volsgBackground = toRgb8(s.background);
    if (framed) {
        const ChildResult volsg = runInChild(
            [&] {
                writePng8(files.volsgPng,
                          renderWithVolsg(files.framed, s.width, s.height, s.background));
                return std::string();
            },
            s.timeout);
        if (volsg.ok)
            row.volsgRendered = true;
        else
            row.renderError = shorten(volsg.problem);
    }

    // 5. Coin reads volsg's write-back of the original; any message is a failure.
    if (!row.readOk) {
        row.writeBackError = "volsg did not read the model";
    } else if (!writeProblem.empty()) {
        row.writeBackError = writeProblem;
    } else {
        const std::string folder = fs::path(m.path).parent_path().string();
        const ChildResult back = runInChild(
            [&] {
                bool readOk = false;
                const std::vector<std::string> messages =
                    coinReadMessages(files.writeBack, folder, readOk);
                Fields fields = messageFields(messages);
                fields["read"] = readOk ? "1" : "0";
                return encodeFields(fields);
            },
            s.timeout);
        if (!back.ok) {
            row.writeBackError = "Coin " + shorten(back.problem);
        } else {
            const Fields f = decodeFields(back.output);
            const std::string messages = messageSummary(f);
            const bool readOk = f.count("read") && f.at("read") == "1";
            if (readOk && messages.empty())
                row.writeBackOk = true;
            else
                row.writeBackError = messages.empty() ? "SoDB::readAll failed" : shorten(messages);
        }
    }

    // Compare and draw.
    Image8 coinImage, volsgImage;
    try {
        if (row.coinRendered) coinImage = readPng8(files.coinPng);
        if (row.volsgRendered) volsgImage = readPng8(files.volsgPng);
        if (row.coinRendered && row.volsgRendered) {
            row.comparison = compare(coinImage, coinBackground, volsgImage, volsgBackground);
            row.compared = true;
            if (row.comparison.pixelsA == 0)
                notes.push_back("Coin's image is empty: nothing to compare");
        }
        writePng8(files.sideBySide,
                  sideBySide(row.coinRendered ? &coinImage : nullptr, coinBackground,
                             row.volsgRendered ? &volsgImage : nullptr, volsgBackground, s.width,
                             s.height));
    } catch (const std::exception& e) {
        notes.push_back("comparing: " + shorten(e.what()));
    }

    std::string joined;
    for (const std::string& n : notes)
        joined += (joined.empty() ? "" : "; ") + n;
    row.notes = oneLine(joined, 2 * maxMessageLength);
    return row;
}

/// Runs the models, `jobs` at a time, each in a worker process; prints rows in order.
std::vector<ModelRow> runAll(const Settings& s, const std::vector<Model>& models) {
    std::vector<ModelRow> rows(models.size());
    std::vector<bool> done(models.size(), false);
    std::deque<std::size_t> pending;
    for (std::size_t i = 0; i < models.size(); ++i)
        pending.push_back(i);
    std::map<std::size_t, RunningChild> running;
    std::size_t printed = 0, finished = 0;
    const double workerTimeout = 5.0 * s.timeout + 30.0; // five steps and the comparison
    std::printf("%s\n", tableHeader().c_str());
    while (!pending.empty() || !running.empty()) {
        while (!pending.empty() && int(running.size()) < s.jobs) {
            const std::size_t i = pending.front();
            pending.pop_front();
            running.emplace(i, startChild([&, i] { return serialize(processModel(s, models[i])); },
                                          workerTimeout));
        }
        std::vector<RunningChild*> children;
        for (auto& [i, child] : running)
            children.push_back(&child);
        pollChildren(children, 500);
        for (auto it = running.begin(); it != running.end();) {
            if (!childDone(it->second)) {
                ++it;
                continue;
            }
            const std::size_t i = it->first;
            const ChildResult result = finishChild(it->second);
            it = running.erase(it);
            ModelRow row;
            try {
                if (!result.ok) throw volsg::Error("its worker " + result.problem);
                row = deserialize(result.output);
            } catch (const std::exception& e) {
                row = ModelRow();
                row.model = models[i].shown;
                row.header = headerKind(models[i].path);
                row.readError = row.writeBackError = "not measured";
                row.notes = oneLine(std::string("the comparison failed: ") + e.what());
            }
            rows[i] = row;
            done[i] = true;
            ++finished;
            std::fprintf(stderr, "[%zu/%zu] %s: read %s, IoU %s, agree %s\n", finished,
                         models.size(), row.model.c_str(), row.readOk ? "ok" : "error",
                         formatIoU(row).c_str(), row.agree() ? "yes" : "no");
        }
        while (printed < models.size() && done[printed]) {
            std::printf("%s\n", tableLine(rows[printed]).c_str());
            std::fflush(stdout);
            ++printed;
        }
    }
    return rows;
}

void writeTextFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw volsg::Error("cannot write " + path);
}

/// The tool checking itself (--verify): a list of failures, empty when all is well.
std::vector<std::string> verify(const Settings& s, const std::vector<Model>& models,
                                const std::vector<ModelRow>& rows) {
    std::vector<std::string> failures;
    auto fail = [&](const std::string& model, const std::string& what) {
        failures.push_back(model + ": " + what);
    };
    if (rows.size() != models.size())
        fail("(all)", std::to_string(rows.size()) + " rows for " + std::to_string(models.size()) +
                          " models");
    const Rgb8 background = toRgb8(s.background);
    for (std::size_t i = 0; i < rows.size() && i < models.size(); ++i) {
        const ModelRow& r = rows[i];
        const Model& m = models[i];
        if (r.model != m.shown) fail(m.shown, "row names '" + r.model + "'");
        for (const std::string* text :
             {&r.readError, &r.renderError, &r.writeBackError, &r.notes}) {
            const std::size_t bound = text == &r.notes ? 2 * maxMessageLength : maxMessageLength;
            if (text->size() > bound || oneLine(*text, bound) != *text)
                fail(m.shown, "a message is not one bounded line: '" + oneLine(*text, 80) + "'");
        }
        if (r.readOk != r.readError.empty()) fail(m.shown, "read flag and error disagree");
        if (r.volsgRendered && !r.renderError.empty())
            fail(m.shown, "render flag and error disagree");
        if (r.writeBackOk != r.writeBackError.empty())
            fail(m.shown, "write-back flag and error disagree");
        const ModelFiles files = filesOf(s, m);
        if (!r.coinRendered) {
            fail(m.shown, "Coin did not render it (" + r.notes + ")");
            continue;
        }
        if (!fs::exists(files.sideBySide)) fail(m.shown, "no side-by-side image");
        try {
            const Image8 coin = readPng8(files.coinPng);
            if (coin.width != s.width || coin.height != s.height)
                fail(m.shown, "Coin's image has the wrong size");
            // Framing: viewAll puts the whole bounding sphere in view, so the model covers a
            // good part of the image (and Coin really drew: a broken GL setup draws nothing).
            int x0 = coin.width, y0 = coin.height, x1 = -1, y1 = -1;
            const std::vector<bool> mask = silhouette(coin, r.coinBackground);
            for (int y = 0; y < coin.height; ++y)
                for (int x = 0; x < coin.width; ++x)
                    if (mask[std::size_t(y) * std::size_t(coin.width) + std::size_t(x)]) {
                        x0 = std::min(x0, x);
                        x1 = std::max(x1, x);
                        y0 = std::min(y0, y);
                        y1 = std::max(y1, y);
                    }
            const int extent = std::max(x1 - x0 + 1, y1 - y0 + 1);
            if (x1 < 0)
                fail(m.shown, "Coin's image is empty");
            else if (extent < std::min(coin.width, coin.height) / 4)
                fail(m.shown, "Coin's image of it spans only " + std::to_string(extent) +
                                  " pixels: not framed");
            if (r.compared) {
                const Image8 volsg = readPng8(files.volsgPng);
                const Comparison c = compare(coin, r.coinBackground, volsg, background);
                const Comparison& rc = r.comparison;
                if (c.pixelsA != rc.pixelsA || c.pixelsB != rc.pixelsB ||
                    c.intersection != rc.intersection || c.unionCount != rc.unionCount ||
                    c.iou != rc.iou || c.colourDifference != rc.colourDifference)
                    fail(m.shown, "the row's numbers do not match its images");
                const Comparison self = compare(coin, r.coinBackground, coin, r.coinBackground);
                if (self.iou != 1.0 || self.colourDifference != 0.0)
                    fail(m.shown, "Coin's image compared with itself does not agree");
            } else if (r.volsgRendered) {
                fail(m.shown, "both rendered but not compared");
            }
        } catch (const std::exception& e) {
            fail(m.shown, oneLine(e.what()));
        }
    }
    if (!s.markdown.empty()) {
        std::ifstream in(s.markdown);
        std::string line;
        std::size_t tableRows = 0;
        while (std::getline(in, line))
            if (line.rfind("| ", 0) == 0) ++tableRows;
        if (tableRows != rows.size() + 2) // and the header and separator lines
            fail(s.markdown, "has " + std::to_string(tableRows) + " table lines for " +
                                 std::to_string(rows.size()) + " rows");
    }
    return failures;
}

std::string commandLine(int argc, char** argv) {
    std::string text = "volsg-coin-compare";
    for (int i = 1; i < argc; ++i)
        text += std::string(" ") + argv[i];
    return text;
}

int run(int argc, char** argv) {
    volsg::cli::Arguments args(argc, argv);
    Settings s;
    while (!args.empty()) {
        const std::string a = args.take();
        if (a == "--out" || a == "-o")
            s.out = args.value(a);
        else if (a == "--markdown")
            s.markdown = args.value(a);
        else if (a == "--size") {
            const glm::ivec2 size = volsg::cli::parseSize(args.value(a));
            s.width = size.x;
            s.height = size.y;
            if (s.width > 4096 || s.height > 4096) throw volsg::Error("--size: at most 4096");
        } else if (a == "--background")
            s.background = volsg::cli::parseColor(args.value(a));
        else if (a == "--jobs")
            s.jobs = args.intValue(a, 1, 64);
        else if (a == "--timeout")
            s.timeout = parseNumber(args.value(a), a, 1.0, 3600.0);
        else if (a == "--require-agree")
            s.requireAgree = parseNumber(args.value(a), a, 0.0, 1.0);
        else if (a == "--expect-models")
            s.expectModels = args.intValue(a, 0, 1000000);
        else if (a == "--view") {
            const std::string v = args.value(a);
            if (v == "front")
                s.view = FramingView::Front;
            else if (v == "oblique")
                s.view = FramingView::Oblique;
            else
                throw volsg::Error("--view wants front or oblique, got '" + v + "'");
        } else if (a == "--verify")
            s.verify = true;
        else if (a == "-h" || a == "--help") {
            std::fputs(usage, stdout);
            return 0;
        } else if (!a.empty() && a[0] == '-')
            throw volsg::Error("unknown option '" + a + "'");
        else
            s.inputs.push_back(a);
    }
    if (s.inputs.empty()) s.inputs.push_back(defaultModels);
    const std::vector<Model> models = findModels(s.inputs);
    fs::create_directories(s.out);

    const auto start = std::chrono::steady_clock::now();
    const std::vector<ModelRow> rows = runAll(s, models);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Summary summary = summarize(rows);
    char timing[128];
    std::snprintf(timing, sizeof timing, "%zu models in %.0f s (%d job%s, %dx%d)", models.size(),
                  seconds, s.jobs, s.jobs == 1 ? "" : "s", s.width, s.height);
    std::printf("summary: %s\n%s\n", summaryLine(summary).c_str(), timing);

    // What stops volsg most often, for the node work: kinds of error over all models.
    std::vector<std::string> readErrors, renderErrors;
    for (const ModelRow& r : rows) {
        if (!r.readOk) readErrors.push_back(r.readError);
        if (!r.renderError.empty()) renderErrors.push_back(r.renderError);
    }
    std::vector<std::string> lackedTypes; // one entry per model that uses the type
    for (const ModelRow& r : rows) {
        std::istringstream types(r.missingTypes);
        for (std::string t; types >> t;)
            lackedTypes.push_back(t);
    }
    const std::string lackedKinds = formatKinds(countKinds(lackedTypes), 100);
    std::printf("node types volsg lacks, by the number of models using them: %s\n",
                lackedKinds.c_str());
    const std::string readKinds = formatKinds(countKinds(readErrors), 8);
    const std::string renderKinds = formatKinds(countKinds(renderErrors), 8);
    std::printf("volsg reading the originals, errors by kind: %s\n", readKinds.c_str());
    std::printf("volsg rendering the framed copies, errors by kind: %s\n", renderKinds.c_str());

    // Mesa may round the clear colour differently from volsg's PNG writer (0.3: 76 and 77);
    // each image is measured against its own background.
    std::string backgrounds;
    const Rgb8 volsgBackground = toRgb8(s.background);
    for (const ModelRow& r : rows) {
        const Rgb8& c = r.coinBackground;
        const std::string text =
            std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]);
        if (r.coinRendered && c != volsgBackground && backgrounds.find(text) == std::string::npos)
            backgrounds += (backgrounds.empty() ? "" : " / ") + text;
    }
    if (!backgrounds.empty())
        std::printf("background: Coin cleared to %s, volsg to %d,%d,%d (8-bit); each image is "
                    "measured against its own\n",
                    backgrounds.c_str(), volsgBackground[0], volsgBackground[1],
                    volsgBackground[2]);

    std::string tsv = tableHeader() + '\n';
    for (const ModelRow& r : rows)
        tsv += tableLine(r) + '\n';
    tsv += "# summary: " + summaryLine(summary) + "\n# " + timing + '\n';
    writeTextFile((fs::path(s.out) / "results.tsv").string(), tsv);
    if (!s.markdown.empty()) {
        const std::string intro =
            "`" + commandLine(argc, argv) + "`: " + timing +
            ".\n\n**Summary: " + summaryLine(summary) +
            ".** Agree: IoU >= 0.9 and colour difference <= 0.08.\n\n" +
            "volsg reading the originals, errors by kind: " + readKinds +
            ".\n\nvolsg rendering the framed copies, errors by kind: " + renderKinds +
            ".\n\nNode types volsg lacks, by the number of models using them: " + lackedKinds +
            ".\n";
        writeTextFile(s.markdown, markdownTable(rows, intro));
    }

    int status = 0;
    if (s.verify) {
        const std::vector<std::string> failures = verify(s, models, rows);
        for (const std::string& f : failures)
            std::fprintf(stderr, "verify: %s\n", f.c_str());
        std::printf("verify: %s\n", failures.empty()
                                        ? "the tool's checks hold"
                                        : (std::to_string(failures.size()) + " failures").c_str());
        if (!failures.empty()) status = 4;
    }
    if (s.expectModels >= 0 && int(models.size()) != s.expectModels) {
        std::fprintf(stderr, "volsg-coin-compare: %zu models, expected %d\n", models.size(),
                     s.expectModels);
        status = 4;
    }
    if (status == 0 && s.requireAgree >= 0.0 && !meetsAgreement(summary, s.requireAgree)) {
        std::fprintf(stderr, "volsg-coin-compare: %d of %d models agree, below the required %g\n",
                     summary.agree, summary.models, s.requireAgree);
        status = 3;
    }
    return status;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "volsg-coin-compare: %s\n", oneLine(e.what()).c_str());
        return 1;
    }
}
