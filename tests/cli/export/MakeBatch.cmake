# The batch test's input: two height maps made by the CLI, one broken file, and a preset.
file(REMOVE_RECURSE batch)
file(MAKE_DIRECTORY batch)
execute_process(COMMAND ${CLI} sample bricks --size 32 --out batch/bricks_height.png COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${CLI} sample stones --size 32 --out batch/stones_depth.png COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${CLI} sample noise --size 32 --out batch/stones_albedo.png COMMAND_ERROR_IS_FATAL ANY)
file(WRITE batch/broken_height.png "not a png")
file(WRITE batch/readme.txt "not an image")
file(WRITE preset.json [=[{"format": "parallax-studio-material", "version": 1,
 "height": {"scale": 0.08}, "technique": {"name": "relief", "maxLayers": 24}}]=])
