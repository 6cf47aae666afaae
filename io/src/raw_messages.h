#pragma once
// The command-line flags that describe raw data, named in every raw-layout error so the
// user knows which one to fix.
namespace voxray::detail {

inline constexpr const char* kRawLayoutFlags = "--raw-dims/--raw-type/--raw-offset";
inline constexpr const char* kRawUsage =
    "for raw data give its layout: --raw-dims X,Y,Z (Z = 0: count the slices) "
    "--raw-type u8|i16|u16|f32 --raw-endian big|little, and --raw-range FIRST-LAST for part "
    "of a folder or of a pattern like CThead.%d (without it: every slice file)";

}  // namespace voxray::detail
