#pragma once
// The viewer's series panel: slider, play/pause, step buttons and play speed for the first
// VolumeSeries of the scene (keys: space plays/pauses, comma and period step).

#include <volsg/core/Object.h>
#include <volsg/series/SeriesPlayer.h>

namespace volsg {

class Node;
class VolumeSeries;

class SeriesPanel {
public:
    SeriesPanel();
    ~SeriesPanel(); // out of line: VolumeSeries is complete only in the source
    SeriesPanel(const SeriesPanel&) = delete;
    SeriesPanel& operator=(const SeriesPanel&) = delete;

    /// Takes the first VolumeSeries under `root` (none: the panel stays hidden).
    void attach(Node* root);
    bool active() const { return bool(series_); }

    void togglePlay(double now);
    void play(double now);
    void pause();
    /// Shows step `step` (clamped), pausing playback.
    void setStep(int step);
    void stepBy(int delta);
    /// Called once per frame: moves playback on. Returns true when the step changed.
    bool update(double now);
    /// Draws its section (a collapsing header) into the current window: the panel column.
    void draw(double now);

private:
    ref_ptr<VolumeSeries> series_;
    SeriesPlayer player_;
};

} // namespace volsg
