# Eigen (header-only), for the small fixed-size linear algebra of the camera model (hal/) and the
# least-squares fits (vision/). Targets link `ringlet_eigen`, never Eigen3::Eigen directly, so
# that every translation unit sees the same configuration:
#
# EIGEN_DONT_VECTORIZE: a simulated run must be bit-identical on x86-64 and aarch64 (README
# "Determinism"). Eigen's NEON double packets compute a*b+c with a fused multiply-add
# (vfmaq_f64) whatever -ffp-contract says, and its packet reductions sum in another order than
# its scalar ones; the scalar path is the same code on every target. The matrices here are 2×2
# and 3×3, where packets gain nothing anyway.
find_package(Eigen3 3.3 CONFIG REQUIRED)
add_library(ringlet_eigen INTERFACE)
target_link_libraries(ringlet_eigen INTERFACE Eigen3::Eigen)
target_compile_definitions(ringlet_eigen INTERFACE EIGEN_DONT_VECTORIZE)
