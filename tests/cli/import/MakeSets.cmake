# Writes the import tests' texture sets with parallax-cli itself, in the working folder:
#   rock/  rock_disp.png (a height map), rock_normal.png (OpenGL green), rock.png (plain albedo)
#   wall/  wall_disp.png (a depth map), wall_normal.png (DirectX green), wall_albedo.png
#   two/   both sets;  broken/  rock_disp.png and a rock_normal.png that is not an image
#   keep.json and its twin keep-twin.json: what a failed import onto keep.json must leave alone.
function(cli)
  execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "parallax-cli ${ARGN} failed")
  endif()
endfunction()
file(REMOVE_RECURSE rock wall two broken)
file(MAKE_DIRECTORY rock wall two broken)
cli(sample noise --size 32 --seed 3 --out rock/rock_disp.png)
cli(bake normal --height rock/rock_disp.png --out rock/rock_normal.png)
cli(sample stones --size 32 --out rock/rock.png)
# wall_disp.png is a depth map: its normal map is baked from it read inverted.
cli(sample stones --size 32 --seed 9 --out wall/wall_disp.png)
cli(bake normal --height wall/wall_disp.png --invert --green directx --out wall/wall_normal.png)
cli(sample noise --size 32 --out wall/wall_albedo.png)
file(GLOB sets rock/* wall/*)
file(COPY ${sets} DESTINATION two)
file(COPY rock/rock_disp.png DESTINATION broken)
file(WRITE broken/rock_normal.png "not an image")
file(REMOVE keep.json keep-twin.json)
cli(import rock --out keep.json)
file(COPY_FILE keep.json keep-twin.json)
