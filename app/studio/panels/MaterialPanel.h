#pragma once
// The material's own settings (what is saved): its name, height scale and how the height map is
// read, tiling and wrap, self-shadow, normals and lighting. Every change is an undoable edit.

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLineEdit;

namespace px::studio {

class MaterialDocument;
struct DocumentState;
class SliderField;

class MaterialPanel : public QWidget {
    Q_OBJECT
public:
    explicit MaterialPanel(MaterialDocument* document, QWidget* parent = nullptr);

    SliderField* heightScale() const { return m_heightScale; }
    SliderField* tiling() const { return m_tiling; }
    SliderField* softness() const { return m_softness; }
    QCheckBox* selfShadow() const { return m_shadow; }
    QCheckBox* depthMap() const { return m_depth; }
    QComboBox* normalGreen() const { return m_normalGreen; }
    QLineEdit* nameField() const { return m_name; }

    // Reads the height file the other way (height <-> depth), as the Depth map box does.
    void flipDepth();

signals:
    void problem(const QString& message); // a file could not be read again
    void note(const QString& message);    // something the status bar should say
    // The wrap mode changed: the cone maps that were there are gone and want baking again.
    void conesInvalidated(bool cone, bool relaxed);

private:
    void refresh();
    void bindSlider(SliderField* field, const QString& text, const QString& key,
                    void (*apply)(DocumentState&, double));
    // Invert and channel change how the height file is read: read it again, or refuse.
    void rereadHeight(const QString& text, bool depth, int channel);
    // "auto" green: the convention the height map's slopes say.
    void tellNormalGreen();

    MaterialDocument* m_document;
    QLineEdit* m_name;
    SliderField* m_heightScale;
    QCheckBox* m_depth;
    QComboBox* m_channel;
    SliderField* m_tiling;
    QComboBox* m_wrap;
    QCheckBox* m_shadow;
    SliderField* m_softness;
    QComboBox* m_normalSource;
    QComboBox* m_normalGreen;
    QComboBox* m_lighting;
    SliderField* m_specular;
    SliderField* m_shininess;
    SliderField* m_roughness;
    SliderField* m_metallic;
};

} // namespace px::studio
