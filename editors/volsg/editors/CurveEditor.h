#pragma once
// Edits one or more MFVec2f fields of control points (transfer-function channels, a Volume's
// planeOpacity) through ControlCurve, each step an undoable edit. Fields change at once, so a
// render in the same frame shows the edit (caches rebuild from the node's version).

#include <string>
#include <vector>

#include <volsg/editors/ControlCurve.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class EditHistory;

class CurveEditor {
public:
    CurveEditor(EditHistory& history, float yMin = 0.0f, float yMax = 1.0f);

    /// The fields edited together (additions, lines, strokes and presets apply to each).
    void setFields(std::vector<MFVec2f*> fields);
    const std::vector<MFVec2f*>& fields() const { return fields_; }
    void setRange(float yMin, float yMax);
    float yMin() const { return yMin_; }
    float yMax() const { return yMax_; }
    ControlCurve curve(std::size_t fieldIndex) const;

    /// Adds the point to every field; returns its index in the first.
    int addPoint(glm::vec2 p);
    /// Removes point `index` of field `fieldIndex`.
    bool deletePoint(std::size_t fieldIndex, int index);
    /// A drag of one point: begin, any number of moves (each shows at once), end (one undo step).
    void beginDrag(std::size_t fieldIndex, int index);
    void dragTo(glm::vec2 p);
    void endDrag();
    bool isDragging() const { return dragField_ >= 0; }
    void drawLine(glm::vec2 a, glm::vec2 b);
    /// Freehand: the stroke is collected point by point; endStroke simplifies it within
    /// `tolerance` into control points (ControlCurve::drawFreehand) as one undo step.
    void beginStroke();
    void addStrokePoint(glm::vec2 p);
    void endStroke(float tolerance);
    bool isStroking() const { return stroking_; }
    const std::vector<glm::vec2>& stroke() const { return stroke_; }
    /// Replaces every edited field's points.
    void setPoints(const std::vector<glm::vec2>& points, const std::string& label);

private:
    std::vector<Field*> asFields() const;
    void store(std::size_t fieldIndex, const ControlCurve& curve);
    EditHistory& history_;
    std::vector<MFVec2f*> fields_;
    float yMin_, yMax_;
    int dragField_ = -1, dragPoint_ = -1;
    bool stroking_ = false;
    std::vector<glm::vec2> stroke_;
};

} // namespace volsg
