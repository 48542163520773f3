#include <volsg/nodes/VolumeSeries.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/core/KeyMixing.h>
#include <volsg/io/ReadContext.h>
#include <volsg/series/FilePattern.h>
#include <volsg/series/MovingSphere.h>
#include <volsg/shearwarp/VoxelObject.h>

namespace volsg {

const EnumValues VolumeSeries::timeGeneratorNames{{"NONE", NO_TIME_GENERATOR},
                                                  {"MOVING_SPHERE", MOVING_SPHERE}};

namespace {

/// More steps than any interactive series has; a bigger range is a typo or a hostile file.
constexpr int kMaxSteps = 100000;
constexpr int kDefaultGeneratedSide = 64;

/// timeSteps as whole numbers first <= last, at most kMaxSteps of them.
std::pair<int, int> stepRange(const glm::vec2& range) {
    for (int a = 0; a < 2; ++a)
        if (!std::isfinite(range[a]) || range[a] != std::floor(range[a]) ||
            std::abs(range[a]) > 1e9f)
            throw Error("VolumeSeries timeSteps must be two whole numbers, got " +
                        std::to_string(range.x) + " " + std::to_string(range.y));
    const auto first = static_cast<long long>(range.x), last = static_cast<long long>(range.y);
    if (last < first) throw Error("VolumeSeries timeSteps: the last step is before the first");
    if (last - first + 1 > kMaxSteps)
        throw Error("VolumeSeries timeSteps " + std::to_string(first) + " " + std::to_string(last) +
                    " make " + std::to_string(last - first + 1) + " steps; at most " +
                    std::to_string(kMaxSteps) + " are allowed");
    return {int(first), int(last)};
}

std::uint64_t mixString(std::uint64_t key, const std::string& s) {
    return mixKey(mixKey(key, std::hash<std::string>{}(s)), s.size());
}

/// Copies every VolumeData field (value and whether it was set) from `from` to `to`.
void copyVolumeDataFields(const VolumeData& from, VolumeData& to) {
    for (std::size_t i = 0; i < to.fieldCount(); ++i) {
        Field* field = to.fieldAt(i);
        field->copyFrom(*from.fieldAt(i));
        field->setDefault(from.fieldAt(i)->isDefault());
    }
}

/// What a file step needs, copied from the node on the render thread: the worker never reads
/// the scene's nodes.
struct FileSeriesSource {
    ref_ptr<VolumeData> layout; // private copy of the raw layout fields
    std::vector<std::string> names;
    std::optional<FilePattern> pattern, tagPattern;
    int first = 0;
    std::string directory;

    SeriesStepVolume load(int index) const {
        // A fresh VolumeData per step reuses its readers and raw-layout rules unchanged.
        ref_ptr<VolumeData> node = VolumeData::create();
        copyVolumeDataFields(*layout, *node);
        node->generator = VolumeData::NONE;
        node->fileName = pattern ? pattern->format(first + index) : names.at(std::size_t(index));
        if (tagPattern) node->tagFileName = tagPattern->format(first + index);
        node->readDone(ReadContext{{}, directory});
        return {node->grid(), node->tagGrid()};
    }
};

} // namespace

VolumeSeries::~VolumeSeries() = default;

void VolumeSeries::readDone(const ReadContext& context) {
    VolumeData::readDone(context);
    directory_ = context.directory;
}

int VolumeSeries::stepCount() const {
    if (timeGenerator() != NO_TIME_GENERATOR || fileNames.empty()) {
        const auto [first, last] = stepRange(timeSteps());
        return last - first + 1;
    }
    if (fileNames.size() > std::size_t(kMaxSteps))
        throw Error("VolumeSeries fileNames lists more than " + std::to_string(kMaxSteps) +
                    " steps");
    return int(fileNames.size());
}

int VolumeSeries::shownStep() const {
    return std::clamp(step(), 0, stepCount() - 1);
}

std::uint64_t VolumeSeries::sourceKeyOfFields() const {
    std::uint64_t key = 0xcbf29ce484222325ULL;
    key = mixString(key, fileName());
    key = mixString(key, tagFileName());
    key = mixString(key, directory_);
    for (const std::string& name : fileNames.getValues())
        key = mixString(key, name);
    for (int a = 0; a < 3; ++a)
        key = mixKey(mixKey(key, bitsOf(dimensions()[a])), bitsOf(spacing()[a]));
    key = mixKey(key, bitsOf(timeSteps().x));
    key = mixKey(key, bitsOf(timeSteps().y));
    key = mixKey(key, spacing.isDefault() ? 1 : 2);
    key = mixKey(key, std::uint64_t(dataType()));
    key = mixKey(key, std::uint64_t(byteOrder()));
    key = mixKey(key, std::uint64_t(headerSkip()));
    key = mixKey(key, std::uint64_t(tagDataType()));
    key = mixKey(key, std::uint64_t(timeGenerator()));
    key = mixKey(key, std::uint64_t(std::int64_t(prefetch())));
    key = mixKey(key, loop() ? 1 : 2);
    return key;
}

SeriesCache& VolumeSeries::cache() const {
    if (cache_ && cacheVersion_ == version()) return *cache_;
    const std::uint64_t key = sourceKeyOfFields();
    const double megabytes = std::max(0.0, double(cacheMegabytes()));
    const auto budget = std::size_t(std::min(megabytes, 1e9) * 1048576.0);
    if (cache_ && key == sourceKey_) {
        cache_->setMemoryBudget(budget);
        cacheVersion_ = version();
        return *cache_;
    }
    cache_.reset(); // its worker stops and its disk folder goes before a new one starts
    lastShown_ = -1;
    const int count = stepCount();
    SeriesStepLoader loader;
    if (timeGenerator() == MOVING_SPHERE) {
        const glm::vec3 d = dimensions();
        if (d.x != d.y || d.y != d.z || d.x != std::floor(d.x) || d.x < 0.0f || d.x > 4096.0f)
            throw Error("VolumeSeries MOVING_SPHERE makes cubic volumes: give equal whole "
                        "dimensions (or 0 0 0 for 64^3)");
        const int n = d.x == 0.0f ? kDefaultGeneratedSide : int(d.x);
        const std::optional<glm::dvec3> setSpacing =
            spacing.isDefault() ? std::nullopt : std::optional(glm::dvec3(spacing()));
        loader = [n, count, setSpacing](int index) {
            const double t = count > 1 ? double(index) / double(count - 1) : 0.0;
            ref_ptr<VolumeGrid> grid = makeMovingSphere(n, t);
            if (setSpacing) grid->setSpacing(*setSpacing);
            return SeriesStepVolume{grid, nullptr};
        };
    } else {
        auto source = std::make_shared<FileSeriesSource>();
        source->layout = VolumeData::create();
        copyVolumeDataFields(*this, *source->layout);
        source->directory = directory_;
        if (!fileNames.empty()) {
            source->names = fileNames.getValues();
            if (!tagFileName().empty())
                throw Error("VolumeSeries with fileNames takes no tagFileName (use patterns)");
        } else {
            if (fileName().empty())
                throw Error("VolumeSeries needs fileNames, a fileName pattern or a timeGenerator");
            source->pattern.emplace(fileName());
            source->first = stepRange(timeSteps()).first;
            if (!tagFileName().empty()) source->tagPattern.emplace(tagFileName());
        }
        loader = [source](int index) { return source->load(index); };
    }
    SeriesCacheSettings settings;
    settings.memoryBudget = budget;
    settings.prefetchSteps = prefetch();
    settings.loop = loop();
    cache_ = std::make_unique<SeriesCache>(count, std::move(loader), settings);
    sourceKey_ = key;
    cacheVersion_ = version();
    return *cache_;
}

void VolumeSeries::showCurrent() const {
    SeriesCache& c = cache();
    const int shown = shownStep();
    if (shown == lastShown_) return;
    int direction = 1;
    if (lastShown_ >= 0) {
        const int count = c.stepCount();
        direction = shown > lastShown_ ? 1 : -1;
        // Playing on past the end wraps: 99 -> 0 is forward, 0 -> 99 backward.
        if (loop() && lastShown_ == count - 1 && shown == 0) direction = 1;
        if (loop() && lastShown_ == 0 && shown == count - 1 && count > 2) direction = -1;
    }
    c.show(shown, direction);
    lastShown_ = shown;
}

ref_ptr<const VolumeGrid> VolumeSeries::grid() const {
    showCurrent();
    return cache().volume(shownStep()).data;
}

ref_ptr<const VolumeGrid> VolumeSeries::tagGrid() const {
    showCurrent();
    return cache().volume(shownStep()).tags;
}

Box3 VolumeSeries::localBounds() const {
    showCurrent();
    std::optional<glm::dvec3> extent = cache().knownExtent(shownStep());
    if (!extent) extent = lastExtent_; // steps of a series share their box, as a rule
    if (!extent) extent = cache().volume(shownStep(), false).data->extent();
    lastExtent_ = extent;
    Box3 box;
    box.extendBy(-0.5 * *extent);
    box.extendBy(0.5 * *extent);
    return box;
}

SeriesStepVolume VolumeSeries::upcomingVolume() const {
    showCurrent();
    const SeriesCache& c = cache();
    const int next = c.nextStep();
    if (next < 0 || next == shownStep()) return {};
    return c.peekVolume(next);
}

ref_ptr<VoxelObject> VolumeSeries::voxelObject(const ExtractionSpec& spec) const {
    showCurrent();
    return cache().voxelObject(shownStep(), spec);
}

void VolumeSeries::setViewAxis(int axis) const {
    cache().setViewAxis(axis);
}

void VolumeSeries::doAction(Action& action) {
    showCurrent();
    VolumeData::doAction(action);
}

} // namespace volsg
