# The plugin must not bring Debian's VTK 9.1 into ParaView's process (which carries its own
# VTK): neither directly nor through PCL's io and surface libraries, which link it.
# Variables: PLUGIN (the plugin library).
execute_process(COMMAND ldd ${PLUGIN} RESULT_VARIABLE code OUTPUT_VARIABLE libraries)
if (NOT code EQUAL 0)
  message(FATAL_ERROR "ldd ${PLUGIN} failed (${code})")
endif ()
string(REGEX MATCHALL "lib(vtk[A-Za-z0-9]*-9\\.1|pcl_io|pcl_surface)[^ ]*" forbidden "${libraries}")
if (forbidden)
  message(FATAL_ERROR "the plugin loads ${forbidden}")
endif ()
if (NOT libraries MATCHES "libvtkCommonCore-pv")
  message(FATAL_ERROR "the plugin does not link ParaView's VTK:\n${libraries}")
endif ()
message(STATUS "the plugin loads no Debian VTK and no PCL io or surface")
