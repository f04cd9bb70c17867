# Writes the import tests' texture sets with parallax-cli itself, in the working folder:
#   rock/  rock_disp.png (a height map), rock_normal.png (OpenGL green), rock.png (plain albedo)
#   wall/  wall_disp.png (a depth map), wall_normal.png (DirectX green), wall_albedo.png
#   two/   both sets;  broken/  rock_disp.png and a rock_normal.png that is not an image
#   keep.json and its twin keep-twin.json: what a failed import onto keep.json must leave alone.
#   acg/    ambientCG names: Bricks076C_1K-PNG_Displacement, _NormalDX (DirectX green), _Color
#   ph/     Poly Haven names: brick_wall_001_disp_1k, _nor_gl_1k, _diff_1k, a grey _arm_1k
#   glued/  stone01.png, stone01z.png (height), stone01n.png (normal): tags glued to the name
#   nothing/  IMG_0001.png and notes.txt: no set
#   nrm/    rock_nrm.png and rock_col.png: a normal map and no height map
include(${CMAKE_CURRENT_LIST_DIR}/../RunCli.cmake)
file(REMOVE_RECURSE rock wall two broken acg ph glued nothing nrm)
file(MAKE_DIRECTORY rock wall two broken acg ph glued nothing nrm)
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
cli(sample stones --size 32 --seed 4 --out acg/Bricks076C_1K-PNG_Displacement.png)
cli(bake normal --height acg/Bricks076C_1K-PNG_Displacement.png --green directx
    --out acg/Bricks076C_1K-PNG_NormalDX.png)
cli(sample noise --size 32 --seed 8 --out acg/Bricks076C_1K-PNG_Color.png)
file(WRITE acg/Bricks076C.mtlx "<materialx/>")
cli(sample bricks --size 32 --seed 5 --out ph/brick_wall_001_disp_1k.png)
cli(bake normal --height ph/brick_wall_001_disp_1k.png --out ph/brick_wall_001_nor_gl_1k.png)
cli(sample noise --size 32 --seed 6 --out ph/brick_wall_001_diff_1k.png)
cli(sample noise --size 32 --seed 7 --out ph/brick_wall_001_arm_1k.png)
cli(sample noise --size 32 --seed 11 --out glued/stone01z.png)
cli(bake normal --height glued/stone01z.png --out glued/stone01n.png)
cli(sample stones --size 32 --seed 12 --out glued/stone01.png)
cli(sample noise --size 32 --seed 13 --out nothing/IMG_0001.png)
file(WRITE nothing/notes.txt "holiday photos")
cli(sample stones --size 32 --seed 14 --out nrm/height-not-shipped.png)
cli(bake normal --height nrm/height-not-shipped.png --out nrm/rock_nrm.png)
file(REMOVE nrm/height-not-shipped.png)
cli(sample noise --size 32 --seed 15 --out nrm/rock_col.png)
file(REMOVE keep.json keep-twin.json)
cli(import rock --out keep.json)
file(COPY_FILE keep.json keep-twin.json)
