#include <volsg/core/Error.h>
#include <volsg/engines/Engine.h>

namespace volsg {

Engine::~Engine() = default;

void Engine::makeOutputs() {
    if (!outputs_.empty()) return;
    for (const OutputSpec& spec : outputSpecs()) {
        std::unique_ptr<Field> f = createFieldOfType(spec.type, nullptr, spec.name);
        if (!f) throw Error(std::string("engine output type ") + spec.type + " does not exist");
        outputs_.push_back(std::move(f));
    }
}

std::size_t Engine::outputCount() const {
    const_cast<Engine*>(this)->makeOutputs();
    return outputs_.size();
}

Field* Engine::outputAt(std::size_t i) {
    makeOutputs();
    return i < outputs_.size() ? outputs_[i].get() : nullptr;
}

Field* Engine::output(std::string_view name) {
    makeOutputs();
    for (const auto& f : outputs_)
        if (name == f->name()) return f.get();
    return nullptr;
}

Field* connectionSourceField(Node& source, std::string_view name) {
    if (Field* f = source.field(name)) return f;
    if (auto* engine = dynamic_cast<Engine*>(&source)) return engine->output(name);
    return nullptr;
}

} // namespace volsg
