// ShpackOptions.cs - what a conversion does besides the projection, named as `shpack convert`'s
// flags (`shpack convert --help`); the defaults are the command's.
namespace Shpack
{
    // How an image holds the sphere (docs/layouts.md): the values of SHPACK_LAYOUT_*.
    public enum ShpackLayout
    {
        Auto = 0,          // from the size: 2:1 equirect, 4:3 hcross, 3:4 vcross, 6:1 hstrip, 1:6 vstrip
        Equirect = 1,      // Skybox/Panoramic's latitude-longitude
        HorizontalCross = 2,
        VerticalCross = 3,
        HorizontalStrip = 4,
        VerticalStrip = 5,
        Octahedral = 6,
        Angular = 7,
        MirrorBall = 8,
    }

    // The world cube faces were made in (`--cube-frame`): the values of SHPACK_CUBE_FRAME_*.
    public enum ShpackCubeFrame { Unity = 0, Gl = 1, ThreeJs = 2 }

    public sealed class ShpackOptions
    {
        public string Method = "exact";  // `--method`: "exact", "center", "mip:K", "mc:N[:SEED]", ...
        public bool NonFiniteAsZero;     // false: NaN/Inf texels are an error
        public bool ClampNegative;       // false: negative texels are kept
        public uint Threads;             // 0: all cores; the result does not depend on it
        public double Intensity = 1.0;   // linear factor on the radiance
        public double ExposureEv;        // the radiance times Intensity * 2^ExposureEv
        public double RotateDeg;         // yaw about +Y, as Skybox/Panoramic's _Rotation
        public string Window = "none";   // "none", "hanning:W", "lanczos:W", "unity", "sloan", "optimal"
        public bool ExtractSun;          // take the sun out of an equirect map as a light
        public uint ExtractLights;       // 0..8: up to this many lights taken out (`--extract-lights`)
        public bool L1;                  // band 2 removed, for Light Probe Proxy Volumes
        public ShpackCubeFrame CubeFrame = ShpackCubeFrame.Unity;  // cube layouts only
    }
}
