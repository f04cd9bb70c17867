# The batch test's input, made by the CLI: texture sets named as artists name them.
#   bricks_height.png                 a height map alone (the old batch suffix)
#   broken_height.png                 not an image
#   textures/rock_boulder_*_1k.png    Poly Haven names one folder down: disp, nor_dx (DirectX
#                                     green), diff, spec
#   stones01z/n/.png, stones01_orm    tags glued to the name, a depth map (its normal map says
#                                     so), a grey ORM (occlusion only)
#   tiles_nrm.png                     a normal map and no height map
#   readme.txt                        no set
include(${CMAKE_CURRENT_LIST_DIR}/../RunCli.cmake)
file(REMOVE_RECURSE batch)
file(MAKE_DIRECTORY batch/textures)
cli(sample bricks --size 32 --out batch/bricks_height.png)
file(WRITE batch/broken_height.png "not a png")
cli(sample noise --size 32 --seed 21 --out batch/textures/rock_boulder_disp_1k.png)
cli(bake normal --height batch/textures/rock_boulder_disp_1k.png --green directx
    --out batch/textures/rock_boulder_nor_dx_1k.png)
cli(sample stones --size 32 --seed 22 --out batch/textures/rock_boulder_diff_1k.png)
cli(sample noise --size 32 --seed 23 --out batch/textures/rock_boulder_spec_1k.png)
cli(sample stones --size 32 --seed 24 --out batch/stones01z.png)
cli(bake normal --height batch/stones01z.png --invert --out batch/stones01n.png)
cli(sample noise --size 32 --seed 25 --out batch/stones01.png)
cli(sample noise --size 32 --seed 26 --out batch/stones01_orm.png)
cli(sample noise --size 32 --seed 27 --out tiles-height.png)
cli(bake normal --height tiles-height.png --out batch/tiles_nrm.png)
file(WRITE batch/readme.txt "not an image")
file(WRITE preset.json [=[{"format": "parallax-studio-material", "version": 1,
 "height": {"scale": 0.08}, "technique": {"name": "relief", "maxLayers": 24}}]=])
