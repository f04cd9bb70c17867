#include "panels/MaterialPanel.h"

#include "jobs/BackgroundLoad.h"
#include "model/MapLoading.h"
#include "model/MaterialDocument.h"
#include "parallax/bake/NormalMapBaker.h"
#include "parallax/material/MaterialNames.h"
#include "widgets/Hints.h"
#include "widgets/SliderField.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QStandardItemModel>
#include <QVBoxLayout>

namespace px::studio {

namespace {

QComboBox* comboOf(std::span<const std::string_view> names, const QString& hint, QWidget* parent) {
    auto* combo = new QComboBox(parent);
    for (std::string_view name : names)
        combo->addItem(QString::fromUtf8(name.data(), static_cast<int>(name.size())));
    combo->setToolTip(hint);
    combo->setStatusTip(hint);
    return combo;
}

} // namespace

MaterialPanel::MaterialPanel(MaterialDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);

    m_name = new QLineEdit(this);
    m_name->setToolTip(tr("The material's name: saved in the file and suggested as its file "
                          "name."));
    auto* nameForm = new QFormLayout;
    nameForm->addRow(tr("Name"), m_name);
    layout->addLayout(nameForm);

    auto* surface = new QGroupBox(tr("Surface"), this);
    auto* surfaceLayout = new QVBoxLayout(surface);
    m_heightScale = new SliderField(tr("Height scale"), {0.0, 0.25, 0.0, 100.0, 4, 0.005}, this);
    m_heightScale->setHint(hints::heightScale());
    m_depth = new QCheckBox(tr("Depth map (white = deep)"), this);
    m_depth->setToolTip(hints::depthMap());
    m_depth->setStatusTip(hints::depthMap());
    m_channel = comboOf(heightChannelNames(), hints::heightChannel(), this);
    m_tiling = new SliderField(tr("Tiling"), {0.25, 8.0, 0.001, 10000.0, 3, 0.25}, this);
    m_tiling->setHint(hints::tiling());
    m_wrap = new QComboBox(this);
    m_wrap->addItems({QStringLiteral("repeat"), QStringLiteral("clamp")});
    m_wrap->setToolTip(hints::wrap());
    m_wrap->setStatusTip(hints::wrap());
    auto* readForm = new QFormLayout;
    readForm->addRow(tr("Height channel"), m_channel);
    readForm->addRow(tr("Wrap"), m_wrap);
    surfaceLayout->addWidget(m_heightScale);
    surfaceLayout->addWidget(m_depth);
    surfaceLayout->addLayout(readForm);
    surfaceLayout->addWidget(m_tiling);

    auto* shadow = new QGroupBox(tr("Self-shadow"), this);
    auto* shadowLayout = new QVBoxLayout(shadow);
    m_shadow = new QCheckBox(tr("Self-shadow"), this);
    m_shadow->setToolTip(hints::selfShadow());
    m_shadow->setStatusTip(hints::selfShadow());
    m_softness = new SliderField(tr("Softness"), {0.0, 1.0, 0.0, 1.0, 2, 0.05}, this);
    m_softness->setHint(hints::shadowSoftness());
    shadowLayout->addWidget(m_shadow);
    shadowLayout->addWidget(m_softness);

    auto* shading = new QGroupBox(tr("Shading"), this);
    auto* shadingLayout = new QVBoxLayout(shading);
    auto* shadingForm = new QFormLayout;
    m_normalSource = comboOf(normalSourceNames(), hints::normalSource(), this);
    m_normalGreen = comboOf(normalGreenNames(), hints::normalGreen(), this);
    m_normalGreen->addItem(QStringLiteral("auto"));
    m_normalGreen->setItemData(m_normalGreen->count() - 1,
                               tr("Tell the convention from the height map's slopes."),
                               Qt::ToolTipRole);
    m_lighting = comboOf(lightingModelNames(), hints::lighting(), this);
    shadingForm->addRow(tr("Normals"), m_normalSource);
    shadingForm->addRow(tr("Normal map green"), m_normalGreen);
    shadingForm->addRow(tr("Lighting"), m_lighting);
    m_specular = new SliderField(tr("Specular"), {0.0, 1.0, 0.0, 1.0, 2, 0.05}, this);
    m_shininess = new SliderField(tr("Shininess"), {1.0, 256.0, 1.0, 10000.0, 0, 1.0}, this);
    m_roughness = new SliderField(tr("Roughness"), {0.0, 1.0, 0.0, 1.0, 2, 0.05}, this);
    m_metallic = new SliderField(tr("Metallic"), {0.0, 1.0, 0.0, 1.0, 2, 0.05}, this);
    m_specular->setHint(tr("Blinn-Phong specular strength."));
    m_shininess->setHint(tr("Blinn-Phong exponent: higher is a smaller, sharper highlight."));
    m_roughness->setHint(tr("Roughness where there is no roughness map."));
    m_metallic->setHint(tr("Metalness where there is no metallic map."));
    shadingLayout->addLayout(shadingForm);
    for (SliderField* f : {m_specular, m_shininess, m_roughness, m_metallic})
        shadingLayout->addWidget(f);

    layout->addWidget(surface);
    layout->addWidget(shadow);
    layout->addWidget(shading);

    bindSlider(m_heightScale, tr("Height scale"), QStringLiteral("heightScale"),
               [](DocumentState& s, double v) { s.material.heightScale = static_cast<float>(v); });
    bindSlider(m_tiling, tr("Tiling"), QStringLiteral("tiling"),
               [](DocumentState& s, double v) { s.material.tiling = static_cast<float>(v); });
    bindSlider(
        m_softness, tr("Shadow softness"), QStringLiteral("softness"),
        [](DocumentState& s, double v) { s.material.shadowSoftness = static_cast<float>(v); });
    bindSlider(m_specular, tr("Specular"), QStringLiteral("specular"),
               [](DocumentState& s, double v) { s.material.specular = static_cast<float>(v); });
    bindSlider(m_shininess, tr("Shininess"), QStringLiteral("shininess"),
               [](DocumentState& s, double v) { s.material.shininess = static_cast<float>(v); });
    bindSlider(m_roughness, tr("Roughness"), QStringLiteral("roughness"),
               [](DocumentState& s, double v) { s.material.roughness = static_cast<float>(v); });
    bindSlider(m_metallic, tr("Metallic"), QStringLiteral("metallic"),
               [](DocumentState& s, double v) { s.material.metallic = static_cast<float>(v); });

    connect(m_shadow, &QCheckBox::toggled, this, [this](bool on) {
        m_document->edit(on ? tr("Self-shadow on") : tr("Self-shadow off"),
                         [on](DocumentState& s) { s.material.selfShadow = on; });
    });
    connect(m_wrap, &QComboBox::currentIndexChanged, this, [this](int i) {
        // Cones are baked for one wrap mode (what lies across the edge): they go with it, and
        // the window bakes them again for the new one.
        const DocumentState& now = m_document->state();
        const bool cone = now.hasMap(MapKind::Cone), relaxed = now.hasMap(MapKind::RelaxedCone);
        m_document->edit(tr("Wrap"), [=](DocumentState& s) {
            s.material.wrap = i == 0 ? WrapMode::Repeat : WrapMode::Clamp;
            if (cone || relaxed) {
                auto assets = std::make_shared<MaterialAssets>(*s.assets);
                assets->cone = {};
                assets->relaxedCone = {};
                s.assets = std::move(assets);
                for (MapKind kind : {MapKind::Cone, MapKind::RelaxedCone}) {
                    mapPath(s.material.maps, kind).clear();
                    s.setUnsaved(kind, false);
                }
            }
        });
        if (cone || relaxed) {
            emit note(tr("The cone maps are baked again for the new wrap mode."));
            emit conesInvalidated(cone, relaxed);
        }
    });
    connect(m_normalSource, &QComboBox::currentIndexChanged, this, [this](int i) {
        const auto source = parseNormalSource(normalSourceNames()[static_cast<std::size_t>(i)]);
        m_document->edit(tr("Normals"), [source](DocumentState& s) {
            s.material.normalSource = source.value_or(NormalSource::HeightCentral);
        });
    });
    connect(m_normalGreen, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (static_cast<std::size_t>(i) >= normalGreenNames().size())
            return tellNormalGreen();
        const auto green = parseNormalGreen(normalGreenNames()[static_cast<std::size_t>(i)]);
        m_document->edit(tr("Normal map green"), [green](DocumentState& s) {
            s.material.normalGreen = green.value_or(NormalGreen::OpenGL);
        });
    });
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const std::string name = m_name->text().trimmed().toStdString();
        if (name.empty())
            return refresh();
        m_document->edit(tr("Rename"), [name](DocumentState& s) { s.material.name = name; });
    });
    connect(m_lighting, &QComboBox::currentIndexChanged, this, [this](int i) {
        const auto model = parseLightingModel(lightingModelNames()[static_cast<std::size_t>(i)]);
        m_document->edit(tr("Lighting"), [model](DocumentState& s) {
            s.material.lighting = model.value_or(LightingModel::BlinnPhong);
        });
    });
    connect(m_depth, &QCheckBox::toggled, this, [this](bool on) {
        rereadHeight(on ? tr("Read height as depth") : tr("Read height as height"), on,
                     m_channel->currentIndex());
    });
    connect(m_channel, &QComboBox::currentIndexChanged, this,
            [this](int i) { rereadHeight(tr("Height channel"), m_depth->isChecked(), i); });

    connect(document, &MaterialDocument::changed, this, &MaterialPanel::refresh);
    refresh();
}

void MaterialPanel::bindSlider(SliderField* field, const QString& text, const QString& key,
                               void (*apply)(DocumentState&, double)) {
    connect(field, &SliderField::valueEdited, this, [this, text, key, apply](double v) {
        m_document->edit(
            text, [apply, v](DocumentState& s) { apply(s, v); }, key);
    });
    connect(field, &SliderField::editFinished, m_document, &MaterialDocument::endMerge);
}

void MaterialPanel::rereadHeight(const QString& text, bool depth, int channel) {
    DocumentState next = m_document->state();
    next.material.heightIsDepth = depth;
    next.material.heightChannel =
        parseHeightChannel(heightChannelNames()[static_cast<std::size_t>(channel)])
            .value_or(HeightChannel::Red);
    Result<Loaded> loaded = loadInBackground<Loaded>(window(), tr("the height map"),
                                                     [next] { return reloadHeight(next); });
    if (!loaded) {
        refresh(); // show the settings as they still are
        if (loaded.error().cancelled())
            return;
        emit problem(QString::fromStdString(loaded.error().message));
        return;
    }
    m_document->edit(text, [&](DocumentState& s) { s = loaded->state; });
    for (const std::string& n : loaded->notes)
        emit note(QString::fromStdString(n));
}

void MaterialPanel::tellNormalGreen() {
    const DocumentState& s = m_document->state();
    Result<NormalGreen> green = detectNormalGreen(
        s.assets->normal, s.assets->height, s.material.wrap,
        s.material.maps.normal.empty() ? "the normal map" : s.material.maps.normal);
    if (!green) {
        refresh();
        emit problem(QString::fromStdString(green.error().message));
        return;
    }
    const NormalGreen told = *green;
    m_document->edit(tr("Normal map green"),
                     [told](DocumentState& next) { next.material.normalGreen = told; });
    refresh(); // "auto" shows what it found
    emit note(tr("The normal map's green is %1, told from the height map's slopes.")
                  .arg(told == NormalGreen::OpenGL ? tr("OpenGL (Y+)") : tr("DirectX (Y-)")));
}

void MaterialPanel::flipDepth() {
    if (m_depth->isEnabled())
        m_depth->toggle();
}

void MaterialPanel::refresh() {
    const DocumentState& s = m_document->state();
    const Material& m = s.material;
    if (!m_name->hasFocus())
        m_name->setText(QString::fromStdString(m.name));
    m_heightScale->setValue(m.heightScale);
    m_tiling->setValue(m.tiling);
    m_softness->setValue(m.shadowSoftness);
    m_specular->setValue(m.specular);
    m_shininess->setValue(m.shininess);
    m_roughness->setValue(m.roughness);
    m_metallic->setValue(m.metallic);
    auto setIndex = [](QComboBox* combo, std::string_view name) {
        const QSignalBlocker block(combo);
        combo->setCurrentIndex(
            combo->findText(QString::fromUtf8(name.data(), static_cast<int>(name.size()))));
    };
    setIndex(m_wrap, toString(m.wrap));
    setIndex(m_normalSource, toString(m.normalSource));
    setIndex(m_normalGreen, toString(m.normalGreen));
    setIndex(m_lighting, toString(m.lighting));
    setIndex(m_channel, toString(m.heightChannel));
    {
        const QSignalBlocker a(m_depth), b(m_shadow);
        m_depth->setChecked(m.heightIsDepth);
        m_shadow->setChecked(m.selfShadow);
    }
    // Invert and channel re-read the height file; a height map made here has none.
    const bool fromFile =
        s.hasMap(MapKind::Height) && !s.isUnsaved(MapKind::Height) && !m.maps.height.empty();
    m_depth->setEnabled(fromFile);
    m_channel->setEnabled(fromFile);
    m_softness->setEnabled(m.selfShadow);
    const bool phong = m.lighting == LightingModel::BlinnPhong;
    m_specular->setVisible(phong);
    m_shininess->setVisible(phong);
    m_roughness->setVisible(!phong);
    m_metallic->setVisible(!phong);
    m_normalGreen->setEnabled(m.normalSource == NormalSource::Map);
    if (auto* model = qobject_cast<QStandardItemModel*>(m_normalGreen->model())) {
        if (QStandardItem* item = model->item(m_normalGreen->count() - 1))
            item->setEnabled(s.hasMap(MapKind::Normal) && s.hasMap(MapKind::Height));
    }
    // "map" needs a normal map: load or bake one first.
    if (auto* model = qobject_cast<QStandardItemModel*>(m_normalSource->model())) {
        const int mapIndex = m_normalSource->findText(QStringLiteral("map"));
        if (QStandardItem* item = model->item(mapIndex)) {
            item->setEnabled(s.hasMap(MapKind::Normal));
            item->setToolTip(s.hasMap(MapKind::Normal)
                                 ? QString()
                                 : tr("Load or bake a normal map first (Maps panel)."));
        }
    }
}

} // namespace px::studio
