# The folders of the solid library, one per layer, lower layers first; a
# folder includes only folders before it in this list
# (docs/architecture.md):
#   core      errors, tensors, the entries interface of parameters
#   materials neo-Hookean, Maxwell branches, volumetric laws
#   elements  shapes, quadrature, the mesh, element kernels
#   model     model, contributions, state snapshot, point probes
#   loads     nodal and pressure loads
#   contact   rigid sphere
#   io        mesh reader, HDF5 layer, results, checkpoints
#   drivers   Newton, explicit, indentation driver
# Headers are included flat ("Model.H", as in OpenFOAM): every folder is an
# include directory. Used by src/solid/CMakeLists.txt and the fuzz build
# (tests/fuzz/project); wmake sees the same headers through
# src/solid/lnInclude (./Allwmake).
set(solidFolders core materials elements model loads contact io drivers)

# solidSources(<var> <root of src/solid>): the library's sources
function(solidSources var dir)
    set(sources)
    foreach(folder ${solidFolders})
        file(GLOB found CONFIGURE_DEPENDS "${dir}/${folder}/*.C")
        list(APPEND sources ${found})
    endforeach()
    set(${var} ${sources} PARENT_SCOPE)
endfunction()
