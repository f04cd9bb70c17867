# The layers of core/ and app/, the one place their order is written down (docs/development.md,
# "Layering"). Each entry is "LAYER: LAYERS" where LAYERS are the layers directly below it; a
# layer may include its own headers and those of every layer below it, directly or through
# others, and nothing else. So no layer includes one above it or beside it, and there is no
# cycle between layers. px_check_layers (PxLayerCheck.cmake) also refuses include cycles between
# files within a layer.
#
# A layer is a folder: "core/X" is core/src/X and core/include/parallax/X; any other name is that
# folder of the source tree. A file belongs to the deepest layer folder holding it ("core" holds
# core/include/parallax/Result.h; a new core/src/Y falls into "core" until it has a line here,
# and then may include nothing, so the check fails until it is placed).
set(PX_LAYERS
  "core:"
  "core/io: core"
  "core/glsl: core"
  "core/image: core/io"
  "core/heightfield: core/image"
  "core/light: core/image"
  "core/mesh: core/image"
  "core/sample: core/heightfield"
  "core/bake: core/heightfield core/glsl"
  "core/trace: core/bake"
  # The mesh bake: the bakers' controls below it, the mesh loader's checks beside it.
  "core/meshbake: core/bake core/mesh"
  "core/engine: core/trace"
  "core/material: core/trace"
  "core/shader: core/material"
  "core/eval: core/engine core/material core/sample"
  "core/export: core/eval core/shader"
  # parallax-render: the OpenGL renderer, on all of the core.
  "app/render: core/export core/light core/mesh"
  "app/cli: app/render core/meshbake"
  # The editor: the document model (no widgets, no GL) at the bottom, the window at the top.
  "app/studio/model: core/export core/light core/mesh"
  "app/studio/widgets: app/studio/model"
  "app/studio/jobs: app/studio/model app/render core/meshbake"
  "app/studio/preview: app/studio/jobs app/studio/widgets"
  "app/studio/panels: app/studio/preview"
  "app/studio/window: app/studio/panels"
  "app/studio: app/studio/window"
)
# Where a quoted #include is looked for after the including file's own folder, as the targets'
# include directories say (core/CMakeLists.txt, app/*/CMakeLists.txt). An include found nowhere
# (a generated header, a system one) is not checked.
set(PX_INCLUDE_ROOTS core/include core/src shaders app/render/include app/studio app/cli)
