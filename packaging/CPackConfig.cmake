# `cpack -G DEB` in a build directory makes a Debian package of the facet executable.
set(CPACK_PACKAGE_NAME "facet")
set(CPACK_PACKAGE_VENDOR "Facet developers")
set(CPACK_PACKAGE_CONTACT "facet@example.invalid")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_GENERATOR "DEB;TGZ")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION "graphics")
include(CPack)
