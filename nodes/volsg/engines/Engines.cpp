#include <volsg/core/Error.h>
#include <volsg/engines/Engines.h>
#include <volsg/math/TransformParts.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace volsg {

namespace {

/// Value i of a list input: its last value past its end, `fallback` when it is empty.
template <class T> T at(const std::vector<T>& values, std::size_t i, T fallback = T{}) {
    if (values.empty()) return fallback;
    return values[std::min(i, values.size() - 1)];
}
bool at(const std::vector<bool>& values, std::size_t i) {
    if (values.empty()) return false;
    return values[std::min(i, values.size() - 1)];
}

std::size_t longest(std::initializer_list<std::size_t> sizes) {
    std::size_t n = 0;
    for (std::size_t s : sizes)
        n = std::max(n, s);
    return n;
}

/// The scene time as an engine sees it: its timeIn when connected, else the evaluator's.
double timeOf(const SFTime& timeIn, const EngineContext& context) {
    return timeIn.connection() ? timeIn.getValue() : context.seconds;
}

Rotation rotationOf(const glm::dquat& q) {
    const glm::dquat n = glm::normalize(q);
    const double w = std::clamp(n.w, -1.0, 1.0);
    const double angle = 2.0 * std::acos(w);
    const double s = std::sqrt(std::max(0.0, 1.0 - w * w));
    Rotation r;
    if (s < 1e-12) return r; // identity: the default axis
    r.axis = glm::vec3(n.x / s, n.y / s, n.z / s);
    r.angle = float(angle);
    return r;
}

// The matrix of a transform in Inventor's order, as Transform::matrix()
// (nodes/volsg/nodes/Transform.cpp): T * C * R * SR * S * SR^-1 * C^-1.
glm::dmat4 composeTransform(const glm::vec3& t, const Rotation& r, const glm::vec3& s,
                            const Rotation& so, const glm::vec3& c) {
    const glm::dmat4 I(1.0);
    const glm::dmat4 soM = so.matrix();
    return glm::translate(I, glm::dvec3(t)) * glm::translate(I, glm::dvec3(c)) * r.matrix() * soM *
           glm::scale(I, glm::dvec3(s)) * glm::transpose(soM) * glm::translate(I, -glm::dvec3(c));
}

} // namespace

// ---- time -------------------------------------------------------------------------------------

void ElapsedTime::evaluate(const EngineContext& context) {
    const double now = timeOf(timeIn, context);
    if (!started_) {
        started_ = true;
        last_ = now;
        resets_ = reset.count();
    }
    if (reset.count() != resets_) {
        resets_ = reset.count();
        elapsed_ = 0.0;
    } else if (on() && !pause()) {
        elapsed_ += (now - last_) * double(speed());
    }
    last_ = now;
    set<SFTime>(0, elapsed_);
}

std::int16_t TimeCounter::valueAt(double phase) const {
    const int lo = min(), hi = max(), st = step() == 0 ? 1 : step();
    const int count = std::max(1, (hi - lo) / st + 1);
    double f = phase - std::floor(phase);
    int k = 0;
    const auto& weights = duty();
    if (weights.size() >= std::size_t(count)) {
        // Each value holds for its share of the cycle.
        double total = 0.0;
        for (int i = 0; i < count; ++i)
            total += std::max(0.0f, weights[std::size_t(i)]);
        if (total > 0.0) {
            double acc = 0.0;
            for (k = 0; k < count - 1; ++k) {
                acc += std::max(0.0f, weights[std::size_t(k)]) / total;
                if (f < acc) break;
            }
        }
    } else {
        k = std::min(count - 1, int(f * count));
    }
    return std::int16_t(lo + k * st);
}

void TimeCounter::evaluate(const EngineContext& context) {
    const double now = timeOf(timeIn, context);
    if (!started_) {
        started_ = true;
        last_ = now;
        syncs_ = syncIn.count();
        resetSeen_ = !reset.isDefault();
    }
    if (syncIn.count() != syncs_) {
        syncs_ = syncIn.count();
        phase_ = 0.0;
    }
    if (on()) phase_ += (now - last_) * double(frequency());
    last_ = now;
    if (!reset.isDefault() && !resetSeen_) {
        // Restart the cycle at the reset value.
        resetSeen_ = true;
        const int lo = min(), st = step() == 0 ? 1 : step();
        const int count = std::max(1, (max() - lo) / st + 1);
        phase_ = std::floor(phase_) + double((reset() - lo) / st) / count + 1e-9;
    }
    // A phase no double counts in whole cycles (a huge frequency or clock) keeps its fraction,
    // which is 0 there; a non-finite one (inf times 0) starts over. So the cycle fits an int64.
    if (!std::isfinite(phase_))
        phase_ = 0.0;
    else if (std::abs(phase_) >= 0x1p52)
        phase_ -= std::floor(phase_);
    const auto cycle = std::int64_t(std::floor(phase_));
    if (cycle != cycle_) {
        if (cycle_ >= 0 || cycle > 0) out<SFTrigger>(1).touch();
        cycle_ = cycle;
    }
    set<SFShort>(0, valueAt(phase_));
}

void Counter::evaluate(const EngineContext&) {
    const int lo = min(), hi = max(), st = step() == 0 ? 1 : step();
    if (!started_) {
        started_ = true;
        value_ = lo;
        triggers_ = trigger.count();
        resetSeen_ = !reset.isDefault();
    }
    if (!reset.isDefault() && !resetSeen_) {
        resetSeen_ = true;
        value_ = reset();
    }
    while (triggers_ < trigger.count()) {
        ++triggers_;
        value_ += st;
        if (value_ > hi) {
            value_ = lo;
            out<SFTrigger>(1).touch();
        }
    }
    set<SFShort>(0, std::int16_t(value_));
}

const EnumValues OneShot::flagNames{{"RETRIGGERABLE", RETRIGGERABLE}, {"HOLD_FINAL", HOLD_FINAL}};

void OneShot::evaluate(const EngineContext& context) {
    const double now = timeOf(timeIn, context);
    if (trigger.count() != triggers_) {
        triggers_ = trigger.count();
        if (!disable() && (!active_ || (flags() & RETRIGGERABLE))) {
            active_ = true;
            start_ = now;
        }
    }
    const double length = duration();
    double t = 0.0;
    if (active_) {
        t = now - start_;
        if (t >= length || disable()) {
            active_ = false;
            ran_ = true;
        }
    }
    const bool hold = (flags() & HOLD_FINAL) && ran_ && !active_;
    const double timeOut = active_ ? t : (hold ? length : 0.0);
    set<SFTime>(0, timeOut);
    set<SFBool>(1, active_);
    set<SFFloat>(2, length > 0.0 ? float(std::clamp(timeOut / length, 0.0, 1.0)) : 0.0f);
}

void OnOff::evaluate(const EngineContext&) {
    if (on.count() != seen_[0]) {
        seen_[0] = on.count();
        state_ = true;
    }
    if (off.count() != seen_[1]) {
        seen_[1] = off.count();
        state_ = false;
    }
    if (toggle.count() != seen_[2]) {
        if ((toggle.count() - seen_[2]) % 2 == 1) state_ = !state_;
        seen_[2] = toggle.count();
    }
    set<SFBool>(0, state_);
    set<SFBool>(1, !state_);
}

void TriggerAny::evaluate(const EngineContext&) {
    std::uint64_t total = 0;
    for (const SFTrigger* t :
         {&input0, &input1, &input2, &input3, &input4, &input5, &input6, &input7, &input8, &input9})
        total += t->count();
    if (total != seen_) {
        seen_ = total;
        out<SFTrigger>(0).touch();
    }
}

// ---- logic ------------------------------------------------------------------------------------

void BoolOperation::evaluate(const EngineContext&) {
    const std::size_t n = longest({a().size(), b().size(), operation().size()});
    std::vector<bool> result(n), inverse(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool x = at(a(), i), y = at(b(), i);
        const std::string op = at(operation(), i, std::string("A"));
        bool r = false;
        if (op == "CLEAR")
            r = false;
        else if (op == "SET")
            r = true;
        else if (op == "A")
            r = x;
        else if (op == "NOT_A")
            r = !x;
        else if (op == "B")
            r = y;
        else if (op == "NOT_B")
            r = !y;
        else if (op == "A_OR_B")
            r = x || y;
        else if (op == "NOT_A_OR_B")
            r = !x || y;
        else if (op == "A_OR_NOT_B")
            r = x || !y;
        else if (op == "NOT_A_OR_NOT_B")
            r = !x || !y;
        else if (op == "A_AND_B")
            r = x && y;
        else if (op == "NOT_A_AND_B")
            r = !x && y;
        else if (op == "A_AND_NOT_B")
            r = x && !y;
        else if (op == "NOT_A_AND_NOT_B")
            r = !x && !y;
        else if (op == "A_EQUALS_B")
            r = x == y;
        else if (op == "A_NOT_EQUALS_B")
            r = x != y;
        else
            throw Error("BoolOperation: unknown operation '" + op + "'");
        result[i] = r;
        inverse[i] = !r;
    }
    setValues<MFBool>(0, std::move(result));
    setValues<MFBool>(1, std::move(inverse));
}

// ---- compose and decompose --------------------------------------------------------------------

void ComposeVec2f::evaluate(const EngineContext&) {
    const std::size_t n = longest({x().size(), y().size()});
    std::vector<glm::vec2> v(n);
    for (std::size_t i = 0; i < n; ++i)
        v[i] = {at(x(), i), at(y(), i)};
    setValues<MFVec2f>(0, std::move(v));
}
void ComposeVec3f::evaluate(const EngineContext&) {
    const std::size_t n = longest({x().size(), y().size(), z().size()});
    std::vector<glm::vec3> v(n);
    for (std::size_t i = 0; i < n; ++i)
        v[i] = {at(x(), i), at(y(), i), at(z(), i)};
    setValues<MFVec3f>(0, std::move(v));
}
void ComposeVec4f::evaluate(const EngineContext&) {
    const std::size_t n = longest({x().size(), y().size(), z().size(), w().size()});
    std::vector<glm::vec4> v(n);
    for (std::size_t i = 0; i < n; ++i)
        v[i] = {at(x(), i), at(y(), i), at(z(), i), at(w(), i)};
    setValues<MFVec4f>(0, std::move(v));
}
void DecomposeVec2f::evaluate(const EngineContext&) {
    std::vector<float> x, y;
    for (const glm::vec2& v : vector()) {
        x.push_back(v.x);
        y.push_back(v.y);
    }
    setValues<MFFloat>(0, std::move(x));
    setValues<MFFloat>(1, std::move(y));
}
void DecomposeVec3f::evaluate(const EngineContext&) {
    std::vector<float> c[3];
    for (const glm::vec3& v : vector())
        for (int k = 0; k < 3; ++k)
            c[k].push_back(v[k]);
    for (int k = 0; k < 3; ++k)
        setValues<MFFloat>(std::size_t(k), std::move(c[k]));
}
void DecomposeVec4f::evaluate(const EngineContext&) {
    std::vector<float> c[4];
    for (const glm::vec4& v : vector())
        for (int k = 0; k < 4; ++k)
            c[k].push_back(v[k]);
    for (int k = 0; k < 4; ++k)
        setValues<MFFloat>(std::size_t(k), std::move(c[k]));
}

void ComposeRotation::evaluate(const EngineContext&) {
    const std::size_t n = longest({axis().size(), angle().size()});
    std::vector<Rotation> r(n);
    for (std::size_t i = 0; i < n; ++i)
        r[i] = Rotation{at(axis(), i, glm::vec3(0, 0, 1)), at(angle(), i)};
    setValues<MFRotation>(0, std::move(r));
}

void ComposeRotationFromTo::evaluate(const EngineContext&) {
    const std::size_t n = longest({from().size(), to().size()});
    std::vector<Rotation> r(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 a(at(from(), i, glm::vec3(0, 0, 1)));
        const glm::dvec3 b(at(to(), i, glm::vec3(0, 0, 1)));
        if (glm::length(a) == 0.0 || glm::length(b) == 0.0) continue;
        const glm::dvec3 u = glm::normalize(a), v = glm::normalize(b);
        const double d = std::clamp(glm::dot(u, v), -1.0, 1.0);
        glm::dvec3 axis = glm::cross(u, v);
        if (glm::length(axis) < 1e-12) {
            if (d > 0.0) continue; // the same direction: identity
            // Opposite: half a turn about any axis perpendicular to `from`.
            axis = glm::cross(u, std::abs(u.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
        }
        r[i] = Rotation{glm::vec3(glm::normalize(axis)), float(std::acos(d))};
    }
    setValues<MFRotation>(0, std::move(r));
}

void DecomposeRotation::evaluate(const EngineContext&) {
    std::vector<glm::vec3> axes;
    std::vector<float> angles;
    for (const Rotation& r : rotation()) {
        // Normalised as Inventor's SbRotation keeps it: a unit axis, angle in [0, 2 pi).
        const Rotation n = rotationOf(r.quat());
        axes.push_back(n.axis);
        angles.push_back(n.angle);
    }
    setValues<MFVec3f>(0, std::move(axes));
    setValues<MFFloat>(1, std::move(angles));
}

void ComposeMatrix::evaluate(const EngineContext&) {
    const std::size_t n = longest({translation().size(), rotation().size(), scaleFactor().size(),
                                   scaleOrientation().size(), center().size()});
    std::vector<glm::mat4> m(n);
    for (std::size_t i = 0; i < n; ++i)
        m[i] = glm::mat4(composeTransform(at(translation(), i), at(rotation(), i),
                                          at(scaleFactor(), i, glm::vec3(1.0f)),
                                          at(scaleOrientation(), i), at(center(), i)));
    setValues<MFMatrix>(0, std::move(m));
}

void DecomposeMatrix::evaluate(const EngineContext&) {
    const std::size_t n = longest({matrix().size(), center().size()});
    std::vector<glm::vec3> t(n), s(n);
    std::vector<Rotation> r(n), so(n);
    for (std::size_t i = 0; i < n; ++i) {
        const TransformParts parts = decomposeTransform(
            glm::dmat4(at(matrix(), i, glm::mat4(1.0f))), glm::dvec3(at(center(), i)));
        t[i] = glm::vec3(parts.translation);
        s[i] = glm::vec3(parts.scaleFactor);
        r[i] = rotationOf(parts.rotation);
        so[i] = rotationOf(parts.scaleOrientation);
    }
    setValues<MFVec3f>(0, std::move(t));
    setValues<MFRotation>(1, std::move(r));
    setValues<MFVec3f>(2, std::move(s));
    setValues<MFRotation>(3, std::move(so));
}

void TransformVec3f::evaluate(const EngineContext&) {
    const std::size_t n = longest({vector().size(), matrix().size()});
    std::vector<glm::vec3> p(n), d(n), nd(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dmat4 M(at(matrix(), i, glm::mat4(1.0f)));
        const glm::dvec3 v(at(vector(), i));
        const glm::dvec4 h = M * glm::dvec4(v, 1.0);
        p[i] = glm::vec3(h.w != 0.0 ? glm::dvec3(h) / h.w : glm::dvec3(h));
        d[i] = glm::vec3(glm::dmat3(M) * v);
        const glm::dvec3 nv = glm::transpose(glm::inverse(glm::dmat3(M))) * v;
        nd[i] = glm::length(nv) > 0.0 ? glm::vec3(glm::normalize(nv)) : glm::vec3(0.0f);
    }
    setValues<MFVec3f>(0, std::move(p));
    setValues<MFVec3f>(1, std::move(d));
    setValues<MFVec3f>(2, std::move(nd));
}

// ---- interpolation ----------------------------------------------------------------------------

template <class MFType, const char* Name, const char* OutType>
Interpolate<MFType, Name, OutType>::Interpolate() {
    using V = typename MFType::Value;
    V zero{}, one{};
    if constexpr (std::is_same_v<V, float>) one = 1.0f;
    if constexpr (std::is_same_v<V, Rotation>) one = zero;
    input0.setValues({zero});
    input1.setValues({one});
    input0.setDefault(true);
    input1.setDefault(true);
}

template <class MFType, const char* Name, const char* OutType>
void Interpolate<MFType, Name, OutType>::evaluate(const EngineContext&) {
    using V = typename MFType::Value;
    const std::size_t n = longest({input0().size(), input1().size()});
    const double a = double(alpha());
    std::vector<V> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const V x = at(input0(), i), y = at(input1(), i);
        if constexpr (std::is_same_v<V, Rotation>) {
            out[i] = rotationOf(glm::slerp(x.quat(), y.quat(), a));
        } else if constexpr (std::is_same_v<V, float>) {
            out[i] = float(double(x) * (1.0 - a) + double(y) * a);
        } else {
            using D = glm::vec<V::length(), double>;
            out[i] = V(D(x) * (1.0 - a) + D(y) * a);
        }
    }
    this->template setValues<MFType>(0, std::move(out));
}

template class Interpolate<MFFloat, interpolateFloatName, mfFloatName>;
template class Interpolate<MFVec2f, interpolateVec2fName, mfVec2fName>;
template class Interpolate<MFVec3f, interpolateVec3fName, mfVec3fName>;
template class Interpolate<MFVec4f, interpolateVec4fName, mfVec4fName>;
template class Interpolate<MFRotation, interpolateRotationName, mfRotationName>;

// ---- engines of a type chosen in the file -----------------------------------------------------

TypedEngine::~TypedEngine() = default;

void TypedEngine::syncType() const {
    const std::string& t = type();
    if (t == madeFor_) return;
    auto* self = const_cast<TypedEngine*>(this);
    self->inputs_.clear();
    self->resetOutputs();
    madeFor_ = t;
    outputType_.clear();
    if (t.size() < 3 || t.substr(0, 2) != "MF") return;
    for (const char* name : inputNames()) {
        std::unique_ptr<Field> f = createFieldOfType(t, self, name);
        if (!f) {
            inputs_.clear();
            return;
        }
        inputs_.push_back(std::move(f));
    }
    outputType_ = outputType(t);
    self->touch();
}

std::size_t TypedEngine::fieldCount() const {
    syncType();
    return Node::fieldCount() + inputs_.size();
}

Field* TypedEngine::fieldAt(std::size_t i) {
    syncType();
    const std::size_t own = Node::fieldCount();
    if (i < own) return Node::fieldAt(i);
    return i - own < inputs_.size() ? inputs_[i - own].get() : nullptr;
}

Field* TypedEngine::input(std::size_t i) {
    syncType();
    return i < inputs_.size() ? inputs_[i].get() : nullptr;
}

std::vector<Engine::OutputSpec> TypedEngine::outputSpecs() const {
    syncType();
    if (outputType_.empty()) return {};
    return {{"output", outputType_.c_str()}};
}

void SelectOne::evaluate(const EngineContext&) {
    Field* in = input(0);
    Field* out = outputAt(0);
    if (!in || !out) return;
    // The list cut to value `index`, which converts to the single value of the output.
    const int i = index();
    std::unique_ptr<Field> one = cloneField(*in);
    if (i < 0 || !keepOnlyValue(*one, std::size_t(i))) return;
    assignConverted(*out, *one);
}

void Gate::evaluate(const EngineContext&) {
    Field* in = input(0);
    Field* out = outputAt(0);
    if (!in || !out) return;
    const bool fire = trigger.count() != triggers_;
    triggers_ = trigger.count();
    if (enable() || fire) assignConverted(*out, *in);
}

void Concatenate::evaluate(const EngineContext&) {
    Field* out = outputAt(0);
    if (!out) return;
    std::unique_ptr<Field> all = cloneField(*input(0));
    for (std::size_t i = 1; i < 10; ++i)
        appendValues(*all, *input(i));
    assignConverted(*out, *all);
}

} // namespace volsg
