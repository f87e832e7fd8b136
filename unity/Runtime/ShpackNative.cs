// ShpackNative.cs - P/Invoke wrapper over shpack's C ABI (lib/include/shpack/shpack_c.h):
// an equirect map held in memory (float RGB, top row first) converted to Unity L2 SH, with
// the same numbers as `shpack convert` writes to its JSON document.
//
// The structs mirror shpack_c.h field for field (LayoutKind.Sequential; the header fixes the
// layout on 64-bit platforms). Errors come back as ShpackException with the library's code
// and static message.
using System;
using System.Runtime.InteropServices;
using UnityEngine.Rendering;

namespace Shpack
{
    public enum ShpackMethod { Exact = 0, Center = 1 }

    // What the conversion does besides the projection; the defaults are shpack convert's.
    public sealed class ShpackOptions
    {
        public ShpackMethod Method = ShpackMethod.Exact;
        public bool NonFiniteAsZero;   // false: NaN/Inf texels are an error
        public bool ClampNegative;     // false: negative texels are kept
        public uint Threads;           // 0: all cores; the result does not depend on it
        public double Intensity = 1.0; // linear factor on the radiance
        public double RotateDeg;       // yaw about +Y, as Skybox/Panoramic's _Rotation
        public string Window = "none"; // "none", "hanning:W", "lanczos:W", "unity", "sloan"
    }

    // The result of a conversion: the arrays of shpack_c.h's shpack_result.
    public sealed class ShpackResult
    {
        public double[] RadianceSh;    // 27: L_c,i, channel-major
        public float[] UnitySh;        // 27: SphericalHarmonicsL2 sh[c, i] at 9c + i
        public float[] Shader;         // 28: unity_SHAr, SHAg, SHAb, SHBr, SHBg, SHBb, SHC
        public double[] MinEOverPi;    // 3: lowest E/pi over the sphere per channel
        public ulong NonFiniteTexels, NegativeTexels;

        public SphericalHarmonicsL2 ToSphericalHarmonicsL2()
        {
            return ShpackProbe.FromFloats(UnitySh);
        }
    }

    public sealed class ShpackException : Exception
    {
        public readonly int Code;
        public ShpackException(int code, string message) : base(message) { Code = code; }
    }

    public static class ShpackNative
    {
        // libshpack_c.so, shpack_c.dll, libshpack_c.dylib. On iOS (static linking) this would be "__Internal".
        const string Library = "shpack_c";

        public const int AbiVersion = 1;  // SHPACK_C_ABI_VERSION of the header mirrored here

        [StructLayout(LayoutKind.Sequential)]
        struct Error
        {
            public int code;
            public uint x, y, face;
            public IntPtr message;
        }

        [StructLayout(LayoutKind.Sequential)]
        struct Image
        {
            public IntPtr data;
            public int pixelType;
            public uint width, height, channels;
            public long pixelStride, rowStride;
        }

        [StructLayout(LayoutKind.Sequential)]
        struct Options
        {
            public int method, nonfinite, negative;
            public uint threads;
            public double intensity, rotateDeg;
            [MarshalAs(UnmanagedType.LPStr)] public string window;
        }

        [StructLayout(LayoutKind.Sequential)]
        struct Result
        {
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 27)] public double[] radianceSh;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] minEOverPi;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 9)] public double[] minDirection;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 9)] public double[] windowFactors;
            public ulong nonfiniteTexels, negativeTexels;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 27)] public float[] unitySh;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 28)] public float[] shader;
        }

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        static extern int shpack_abi_version();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        static extern int shpack_convert_equirect(ref Image image, ref Options options, ref Result result, ref Error error);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        static extern int shpack_shade_sh9([In] float[] shader, float x, float y, float z, [Out] float[] rgb);

        // The library this wrapper was written for is the one loaded.
        public static bool IsCompatible()
        {
            return shpack_abi_version() == AbiVersion;
        }

        // Converts a width x height equirect map of `channels` floats per texel (1 grey, 3 RGB,
        // 4 RGBA with alpha ignored), rows from the top, as Unity's Skybox/Panoramic maps it.
        public static ShpackResult ConvertEquirect(float[] pixels, int width, int height, int channels, ShpackOptions options)
        {
            if (pixels == null) throw new ArgumentNullException("pixels");
            if (width <= 0 || height <= 0 || channels <= 0 || (long)width * height * channels > pixels.Length)
                throw new ArgumentException("pixels must hold width * height * channels floats");
            if (options == null) options = new ShpackOptions();
            var native = new Options
            {
                method = (int)options.Method,
                nonfinite = options.NonFiniteAsZero ? 1 : 0,
                negative = options.ClampNegative ? 1 : 0,
                threads = options.Threads,
                intensity = options.Intensity,
                rotateDeg = options.RotateDeg,
                window = options.Window,
            };
            var result = new Result();
            var error = new Error();
            GCHandle pin = GCHandle.Alloc(pixels, GCHandleType.Pinned);
            int code;
            try
            {
                var image = new Image
                {
                    data = pin.AddrOfPinnedObject(),
                    pixelType = 0,  // SHPACK_PIXEL_F32
                    width = (uint)width,
                    height = (uint)height,
                    channels = (uint)channels,
                };
                code = shpack_convert_equirect(ref image, ref native, ref result, ref error);
            }
            finally
            {
                pin.Free();
            }
            if (code != 0)
                throw new ShpackException(code, "shpack: " + Marshal.PtrToStringAnsi(error.message) +
                                                (code == 3 ? " (first at x=" + error.x + ", y=" + error.y + ")" : ""));
            return new ShpackResult
            {
                RadianceSh = result.radianceSh,
                UnitySh = result.unitySh,
                Shader = result.shader,
                MinEOverPi = result.minEOverPi,
                NonFiniteTexels = result.nonfiniteTexels,
                NegativeTexels = result.negativeTexels,
            };
        }

        // Unity's ShadeSH9 in float on the 28 shader floats: E/pi for the normal (x, y, z).
        public static float[] ShadeSH9(float[] shader, float x, float y, float z)
        {
            if (shader == null || shader.Length != 28) throw new ArgumentException("shader must hold 28 floats");
            var rgb = new float[3];
            shpack_shade_sh9(shader, x, y, z, rgb);
            return rgb;
        }
    }
}
