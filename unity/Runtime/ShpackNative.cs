// ShpackNative.cs - environment maps held in memory converted to Unity L2 SH in process, through
// shpack's C library (ShpackInterop, shpack_c.h's shpack_convert), with the numbers `shpack
// convert` writes to its JSON document for the same texels and options.
//
// Pixels are read as linear radiance, as an HDR (float or half) texture holds them; an 8-bit
// sRGB texture's values are taken as they are stored. Errors come back as ShpackException
// with the library's code and static message.
using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;
using UnityEngine;

namespace Shpack
{
    public static class ShpackNative
    {
        public const int AbiVersion = 1;  // SHPACK_C_ABI_VERSION of the header mirrored here
        const int ColorBytes = 16;        // UnityEngine.Color: four floats, r g b a

        // The library this wrapper was written for is the one loaded.
        public static bool IsCompatible()
        {
            return ShpackInterop.shpack_abi_version() == AbiVersion;
        }

        // A width x height equirect map of `channels` floats per texel (1 grey, 3 RGB, 4 RGBA
        // with alpha ignored), rows from the top, as Unity's Skybox/Panoramic maps it.
        public static ShpackResult ConvertEquirect(float[] pixels, int width, int height, int channels, ShpackOptions options)
        {
            return Convert(pixels, width, height, channels, ShpackLayout.Equirect, options);
        }

        // A map of any single-image layout, `channels` floats per texel, rows from the top.
        public static ShpackResult Convert(float[] pixels, int width, int height, int channels, ShpackLayout layout, ShpackOptions options)
        {
            if (pixels == null) throw new ArgumentNullException("pixels");
            if (width <= 0 || height <= 0 || channels <= 0 || (long)width * height * channels > pixels.Length)
                throw new ArgumentException("pixels must hold width * height * channels floats");
            using (var pins = new Pins())
            {
                ShpackInterop.Map map = NewMap((int)layout, options);
                map.image = View(pins.Pin(pixels), width, height, (uint)channels, 0);
                return Run(ref map, options);
            }
        }

        // A Texture2D (Read/Write enabled) in any layout: Auto detects it from the size, as the
        // command does. GetPixels lays rows out bottom to top; the library reads them through a
        // negative row stride, so the map is not copied again.
        public static ShpackResult ConvertTexture(Texture2D texture, ShpackLayout layout = ShpackLayout.Auto, ShpackOptions options = null)
        {
            if (texture == null) throw new ArgumentNullException("texture");
            Color[] pixels = texture.GetPixels();
            using (var pins = new Pins())
            {
                ShpackInterop.Map map = NewMap((int)layout, options);
                map.image = BottomUp(pins.Pin(pixels), texture.width, texture.height);
                return Run(ref map, options);
            }
        }

        // A Cubemap (Read/Write enabled): its six faces in CubemapFace order (+X, -X, +Y, -Y, +Z,
        // -Z), each read with GetPixels(face) with row 0 at the top of the face as
        // docs/conventions.md orients it (Unity's D3D-style face axes).
        public static ShpackResult ConvertCubemap(Cubemap cubemap, ShpackOptions options = null)
        {
            if (cubemap == null) throw new ArgumentNullException("cubemap");
            using (var pins = new Pins())
            {
                ShpackInterop.Map map = NewMap(ShpackInterop.LayoutFaces, options);
                for (int f = 0; f < 6; ++f)
                {
                    Color[] face = cubemap.GetPixels((CubemapFace)f);
                    map.faces[f] = View(pins.Pin(face), cubemap.width, cubemap.width, 4, 0);
                }
                return Run(ref map, options);
            }
        }

        // Unity's ShadeSH9 in float on the 28 shader floats: E/pi for the normal (x, y, z).
        public static float[] ShadeSH9(float[] shader, float x, float y, float z)
        {
            if (shader == null || shader.Length != 28) throw new ArgumentException("shader must hold 28 floats");
            var rgb = new float[3];
            ShpackInterop.shpack_shade_sh9(shader, x, y, z, rgb);
            return rgb;
        }

        static ShpackInterop.Map NewMap(int layout, ShpackOptions options)
        {
            return new ShpackInterop.Map
            {
                structSize = (uint)Marshal.SizeOf(typeof(ShpackInterop.Map)),
                layout = layout,
                cubeFrame = options == null ? 0 : (int)options.CubeFrame,
                faces = new ShpackInterop.Image[6],
            };
        }

        static ShpackInterop.Image View(IntPtr data, int width, int height, uint channels, long rowStride)
        {
            return new ShpackInterop.Image
            {
                data = data,
                pixelType = ShpackInterop.PixelF32,
                width = (uint)width,
                height = (uint)height,
                channels = channels,
                rowStride = rowStride,
            };
        }

        // Colors stored bottom row first: the view starts at the top row, the last one stored.
        static ShpackInterop.Image BottomUp(IntPtr data, int width, int height)
        {
            long row = (long)width * ColorBytes;
            return View(new IntPtr(data.ToInt64() + row * (height - 1)), width, height, 4, -row);
        }

        static ShpackInterop.ConvertOptions NativeOptions(ShpackOptions options)
        {
            if (options == null) options = new ShpackOptions();
            return new ShpackInterop.ConvertOptions
            {
                structSize = (uint)Marshal.SizeOf(typeof(ShpackInterop.ConvertOptions)),
                nonfinite = options.NonFiniteAsZero ? 1 : 0,
                negative = options.ClampNegative ? 1 : 0,
                threads = options.Threads,
                intensity = options.Intensity,
                exposureEv = options.ExposureEv,
                rotateDeg = options.RotateDeg,
                method = options.Method,
                window = options.Window,
                extractSun = options.ExtractSun ? 1 : 0,
                l1 = options.L1 ? 1 : 0,
                extractLights = options.ExtractLights,
            };
        }

        static ShpackResult Run(ref ShpackInterop.Map map, ShpackOptions options)
        {
            ShpackInterop.ConvertOptions native = NativeOptions(options);
            var conversion = new ShpackInterop.Conversion { structSize = (uint)Marshal.SizeOf(typeof(ShpackInterop.Conversion)) };
            var error = new ShpackInterop.Error();
            int code = ShpackInterop.shpack_convert(ref map, ref native, ref conversion, ref error);
            if (code != 0) throw Failure(code, error, map.layout == ShpackInterop.LayoutFaces);
            return ResultOf(conversion);
        }

        static ShpackException Failure(int code, ShpackInterop.Error error, bool faces)
        {
            string where = code != ShpackInterop.NonFiniteTexel ? ""
                         : " (first at x=" + error.x + ", y=" + error.y + (faces ? ", face " + error.face : "") + ")";
            return new ShpackException(code, "shpack: " + Marshal.PtrToStringAnsi(error.message) + where);
        }

        static ShpackResult ResultOf(ShpackInterop.Conversion conversion)
        {
            ShpackInterop.Result sh = conversion.sh;
            var lights = new ShpackLight[conversion.lightCount];
            for (int k = 0; k < lights.Length; ++k)
            {
                ShpackInterop.ExtractedLight extracted = conversion.lights[k];
                lights[k] = LightOf(extracted.light);
                lights[k].ErrorBeforePct = extracted.errorBeforePct;
                lights[k].ErrorAfterPct = extracted.errorAfterPct;
            }
            ShpackInterop.ViewError error = conversion.viewError;
            return new ShpackResult
            {
                RadianceSh = sh.radianceSh,
                UnitySh = sh.unitySh,
                Shader = sh.shader,
                MinEOverPi = sh.minEOverPi,
                NonFiniteTexels = sh.nonfiniteTexels,
                NegativeTexels = sh.negativeTexels,
                Sun = conversion.hasSun == 1 ? LightOf(conversion.sun) : null,
                Lights = lights,
                WindowRmsChange = conversion.windowRmsChange,
                WindowPlanes = conversion.windowPlanes,
                LightCandidates = conversion.lightCandidates,
                ViewError = new ShpackViewError
                {
                    MaxPct = error.maxPct, RmsPct = error.rmsPct, BoundPct = error.boundPct, Directions = error.directions,
                },
            };
        }

        static ShpackLight LightOf(ShpackInterop.Light light)
        {
            return new ShpackLight
            {
                Direction = light.direction,
                Irradiance = light.irradiance,
                Quaternion = light.quaternion,
                Color = light.color,
                ColorSrgb = light.colorSrgb,
                Intensity = light.intensity,
            };
        }

        // The pixel arrays pinned for the length of one call, so the library can read them in
        // place.
        sealed class Pins : IDisposable
        {
            readonly List<GCHandle> handles = new List<GCHandle>();

            public IntPtr Pin(object array)
            {
                GCHandle handle = GCHandle.Alloc(array, GCHandleType.Pinned);
                handles.Add(handle);
                return handle.AddrOfPinnedObject();
            }

            public void Dispose()
            {
                foreach (GCHandle handle in handles) handle.Free();
            }
        }
    }
}
