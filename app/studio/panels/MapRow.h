#pragma once
// One map of the material in the maps panel: a thumbnail, where it comes from (its file, or made
// here and not saved yet), and buttons to load, clear or bake it. Files dropped on the row load
// as this map.

#include "parallax/material/MapKind.h"

#include <QWidget>
#include <memory>

class QImage;
class QBoxLayout;
class QLabel;
class QToolButton;

namespace px::studio {

struct DocumentState;

class MapRow : public QWidget {
    Q_OBJECT
public:
    MapRow(MapKind kind, bool bakeable, QWidget* parent = nullptr);

    MapKind kind() const { return m_kind; }
    void refresh(const DocumentState& state);
    void setBakeEnabled(bool enabled);
    QToolButton* bakeButton() const { return m_bake; }
    QToolButton* loadButton() const { return m_load; }
    QString sourceText() const;
    // A line under the source in warning colour (a baked map out of date); empty hides it.
    void setWarning(const QString& text);
    QString warningText() const;
    // Thumbnails shown so far by every row (tests: a row makes one only when its map changes;
    // a map over 1024² texels gets it from a worker, later).
    static int thumbnailsMade();

signals:
    void loadRequested(px::MapKind kind);
    void clearRequested(px::MapKind kind);
    void bakeRequested(px::MapKind kind);
    void fileDropped(px::MapKind kind, const QString& path);

protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

public:
    QSize minimumSizeHint() const override;

protected:
private:
    // The buttons beside the text where the row is wide enough, under it where not: the row's
    // width is the panel's (its own needs never widen the panel past its dock).
    void arrange(int width);
    QBoxLayout* m_arrangement = nullptr;
    QBoxLayout* m_top = nullptr; // the thumbnail and the texts
    QWidget* m_buttons = nullptr;
    void showThumbnail(const QImage& thumbnail, double ratio);
    MapKind m_kind;
    QLabel* m_thumbnail;
    QLabel* m_title;
    QLabel* m_source;
    QLabel* m_warning;
    QToolButton* m_load;
    QToolButton* m_clear;
    QToolButton* m_bake = nullptr;
    // The texels and size the thumbnail shows: made again only when they change (a thumbnail of
    // an 8192² map reads 64 M texels, and every edit of the material refreshes the rows).
    std::weak_ptr<const void> m_shownTexels;
    int m_shownSide = 0;
    int m_thumbnailSerial = 0; // the latest thumbnail asked for; a worker's older one is dropped
};

} // namespace px::studio
