# The folders of the solid library, one per layer (lower layers first):
# core (errors, tensors), materials, elements (shapes, quadrature, element
# kernels), model (mesh, model, contributions), loads, contact, drivers,
# io (mesh reader, HDF5 layer, results, checkpoints). Headers are
# included flat ("Model.H", as in OpenFOAM): every folder is an include
# directory. Used by src/solid/CMakeLists.txt and the fuzz build
# (tests/fuzz/project); wmake sees the same headers through
# src/solid/lnInclude (./Allwmake).
set(solidFolders core materials elements model loads contact drivers io)

# solidSources(<var> <root of src/solid>): the library's sources
function(solidSources var dir)
    set(sources)
    foreach(folder ${solidFolders})
        file(GLOB found CONFIGURE_DEPENDS "${dir}/${folder}/*.C")
        list(APPEND sources ${found})
    endforeach()
    set(${var} ${sources} PARENT_SCOPE)
endfunction()
