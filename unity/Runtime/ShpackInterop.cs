// ShpackInterop.cs - the structs and functions of shpack's C ABI (lib/include/shpack/shpack_c.h),
// mirrored field for field for P/Invoke. The header fixes every layout on 64-bit platforms
// with no hidden padding except shpack_result's 4 tail bytes, which Sequential layout adds
// too (the struct is 8-byte aligned); the library refuses a struct_size that is neither its
// own sizeof nor its first release's, so a wrong mirror fails loudly rather than reading garbage.
using System;
using System.Runtime.InteropServices;

namespace Shpack
{
    static class ShpackInterop
    {
        // libshpack_c.so, shpack_c.dll, libshpack_c.dylib (unity/Plugins/<platform>/). IL2CPP on
        // iOS would need "__Internal" and a static library, which shpack does not build.
        const string Library = "shpack_c";

        public const int LayoutFaces = 9;   // SHPACK_LAYOUT_FACES
        public const int PixelF32 = 0;      // SHPACK_PIXEL_F32
        public const int NonFiniteTexel = 3; // SHPACK_NONFINITE_TEXEL

        [StructLayout(LayoutKind.Sequential)]
        public struct Error
        {
            public int code;
            public uint x, y, face;
            public IntPtr message;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct Image
        {
            public IntPtr data;
            public int pixelType;
            public uint width, height, channels;
            public long pixelStride, rowStride;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct Map
        {
            public uint structSize;
            public int layout, cubeFrame;
            public uint reserved;
            public Image image;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 6)] public Image[] faces;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct ConvertOptions
        {
            public uint structSize;
            public int nonfinite, negative;
            public uint threads;
            public double intensity, exposureEv, rotateDeg;
            [MarshalAs(UnmanagedType.LPStr)] public string method;
            [MarshalAs(UnmanagedType.LPStr)] public string window;
            public int extractSun, l1;
            public uint extractLights, reserved;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct Result
        {
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 27)] public double[] radianceSh;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] minEOverPi;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 9)] public double[] minDirection;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 9)] public double[] windowFactors;
            public ulong nonfiniteTexels, negativeTexels;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 27)] public float[] unitySh;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 28)] public float[] shader;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct Light
        {
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] direction;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] irradiance;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] skyLevel;
            public double angularRadiusDeg, solidAngleSr;
            public ulong texels;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] forward;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] eulerDeg;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 4)] public double[] quaternion;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] color;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] colorSrgb;
            public double intensity;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct ViewError
        {
            public double maxPct, rmsPct, boundPct;
            public uint directions, reserved;
        }

        [StructLayout(LayoutKind.Sequential)]
        public struct ExtractedLight
        {
            public Light light;
            public double errorBeforePct, errorAfterPct;
        }

        public const int MaxExtractedLights = 8;  // SHPACK_MAX_EXTRACTED_LIGHTS

        [StructLayout(LayoutKind.Sequential)]
        public struct Conversion
        {
            public uint structSize;
            public int hasSun;
            public Result sh;
            public Light sun;
            public ViewError viewError;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public double[] windowRmsChange;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)] public int[] windowPlanes;
            public int windowImpossible;
            public uint lightCount, lightCandidates;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = MaxExtractedLights)] public ExtractedLight[] lights;
        }

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern int shpack_abi_version();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern int shpack_convert(ref Map map, ref ConvertOptions options, ref Conversion conversion, ref Error error);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern int shpack_shade_sh9([In] float[] shader, float x, float y, float z, [Out] float[] rgb);
    }
}
