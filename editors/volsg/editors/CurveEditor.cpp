#include <volsg/editors/CurveEditor.h>

#include <volsg/editors/EditHistory.h>

namespace volsg {

CurveEditor::CurveEditor(EditHistory& history, float yMin, float yMax)
    : history_(history), yMin_(yMin), yMax_(yMax) {}

void CurveEditor::setFields(std::vector<MFVec2f*> fields) {
    if (isDragging()) endDrag();
    stroking_ = false;
    fields_ = std::move(fields);
}

void CurveEditor::setRange(float yMin, float yMax) {
    yMin_ = yMin;
    yMax_ = yMax;
}

ControlCurve CurveEditor::curve(std::size_t i) const {
    return ControlCurve(fields_.at(i)->getValues(), yMin_, yMax_);
}

std::vector<Field*> CurveEditor::asFields() const {
    return std::vector<Field*>(fields_.begin(), fields_.end());
}

void CurveEditor::store(std::size_t i, const ControlCurve& c) {
    if (fields_[i]->getValues() != c.points()) fields_[i]->setValues(c.points());
}

int CurveEditor::addPoint(glm::vec2 p) {
    if (fields_.empty()) return -1;
    history_.begin("add point", asFields());
    int first = -1;
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        ControlCurve c = curve(i);
        const int at = c.add(p);
        if (i == 0) first = at;
        store(i, c);
    }
    history_.commit();
    return first;
}

bool CurveEditor::deletePoint(std::size_t fieldIndex, int index) {
    if (fieldIndex >= fields_.size()) return false;
    ControlCurve c = curve(fieldIndex);
    history_.begin("delete point", {fields_[fieldIndex]});
    const bool removed = c.remove(index);
    store(fieldIndex, c);
    history_.commit();
    return removed;
}

void CurveEditor::beginDrag(std::size_t fieldIndex, int index) {
    if (fieldIndex >= fields_.size() || index < 0 ||
        std::size_t(index) >= fields_[fieldIndex]->size())
        return;
    dragField_ = int(fieldIndex);
    dragPoint_ = index;
    history_.begin("move point", {fields_[fieldIndex]});
}

void CurveEditor::dragTo(glm::vec2 p) {
    if (!isDragging()) return;
    ControlCurve c = curve(std::size_t(dragField_));
    c.move(dragPoint_, p);
    store(std::size_t(dragField_), c);
}

void CurveEditor::endDrag() {
    if (!isDragging()) return;
    dragField_ = dragPoint_ = -1;
    history_.commit();
}

void CurveEditor::drawLine(glm::vec2 a, glm::vec2 b) {
    if (fields_.empty()) return;
    history_.begin("line", asFields());
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        ControlCurve c = curve(i);
        c.drawLine(a, b);
        store(i, c);
    }
    history_.commit();
}

void CurveEditor::beginStroke() {
    stroking_ = true;
    stroke_.clear();
}

void CurveEditor::addStrokePoint(glm::vec2 p) {
    if (stroking_) stroke_.push_back(p);
}

void CurveEditor::endStroke(float tolerance) {
    if (!stroking_) return;
    stroking_ = false;
    if (stroke_.empty() || fields_.empty()) return;
    history_.begin("freehand", asFields());
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        ControlCurve c = curve(i);
        c.drawFreehand(stroke_, tolerance);
        store(i, c);
    }
    history_.commit();
    stroke_.clear();
}

void CurveEditor::setPoints(const std::vector<glm::vec2>& points, const std::string& label) {
    if (fields_.empty()) return;
    history_.begin(label, asFields());
    for (std::size_t i = 0; i < fields_.size(); ++i)
        store(i, ControlCurve(points, yMin_, yMax_));
    history_.commit();
}

} // namespace volsg
