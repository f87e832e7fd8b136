// ShpackMonoTest.cs - the Unity package (unity/) under Mono, without Unity: maps made in
// memory are converted through P/Invoke (ShpackNative over libshpack_c) and by the shpack
// command (from the same texels written as PFM), and the two must agree bit for bit
// (ShpackMonoTestConvert.cs); the editor scripts' commands must put the document's or the
// conversion's exact floats into the stubbed scene, through Undo, with the scene marked
// dirty (ShpackMonoTestEditor.cs); and the command's C# output (the class ShpackStudio,
// compiled into this test) must give the document's floats exactly.
//
// Usage: mono ShpackMonoTest.exe <shpack command> <work folder> <studio.json>
// Exit code 0 when every check passes; each failure is printed.
using System;
using System.Diagnostics;
using System.IO;
using System.Text;
using Shpack;
using UnityEngine;
using UnityEngine.Rendering;

static partial class ShpackMonoTest
{
    static int failures;
    static string cli, work;

    static void Check(bool ok, string what)
    {
        if (ok) return;
        ++failures;
        Console.Error.WriteLine("FAILED: " + what);
    }

    static int Bits(float f) { return BitConverter.ToInt32(BitConverter.GetBytes(f), 0); }

    static void CheckSameFloats(float[] got, float[] want, string what)
    {
        Check(got.Length == want.Length, what + ": length " + got.Length + " != " + want.Length);
        for (int k = 0; k < Math.Min(got.Length, want.Length); ++k)
            Check(Bits(got[k]) == Bits(want[k]), what + "[" + k + "]: " + got[k].ToString("R") + " != " + want[k].ToString("R"));
    }

    static void CheckSameDoubles(double[] got, double[] want, string what)
    {
        Check(got.Length == want.Length, what + ": length " + got.Length + " != " + want.Length);
        for (int k = 0; k < Math.Min(got.Length, want.Length); ++k)
            Check(BitConverter.DoubleToInt64Bits(got[k]) == BitConverter.DoubleToInt64Bits(want[k]),
                  what + "[" + k + "]: " + got[k].ToString("R") + " != " + want[k].ToString("R"));
    }

    static void CheckProbe(SphericalHarmonicsL2 sh, float[] want, string what)
    {
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < 9; ++i)
                Check(Bits(sh[c, i]) == Bits(want[9 * c + i]), what + " sh[" + c + ", " + i + "]");
    }

    // The native result is the command's document: the 27 floats, the 28 shader floats and
    // the 27 radiance doubles as the package's JSON reader reads them back.
    static void CheckResultIsDocument(ShpackResult native, ShpackProbeData document, string what)
    {
        CheckSameFloats(native.UnitySh, document.UnitySh, what + ": sphericalHarmonicsL2");
        CheckSameFloats(native.Shader, document.Shader, what + ": shader");
        CheckSameDoubles(native.RadianceSh, document.RadianceSh, what + ": radiance_sh");
    }

    // A 128 x 64 sky in memory: a vertical gradient, a warm sun disc of 3 degrees at
    // (lon 40, elevation 30 degrees), and a few small negative texels (as lossy EXR has).
    static float[] MakeSky(int width, int height)
    {
        var pixels = new float[width * height * 3];
        double sunLon = 40 * Math.PI / 180, sunElevation = 30 * Math.PI / 180;
        double sx = Math.Cos(sunElevation) * Math.Cos(sunLon), sy = Math.Sin(sunElevation), sz = Math.Cos(sunElevation) * Math.Sin(sunLon);
        for (int y = 0; y < height; ++y)
        {
            for (int x = 0; x < width; ++x)
            {
                // Unity's Skybox/Panoramic mapping (docs/conventions.md).
                double theta = Math.PI * (y + 0.5) / height, lon = (0.5 - (x + 0.5) / width) * 2 * Math.PI;
                double dx = Math.Sin(theta) * Math.Cos(lon), dy = Math.Cos(theta), dz = Math.Sin(theta) * Math.Sin(lon);
                bool sun = dx * sx + dy * sy + dz * sz > Math.Cos(1.5 * Math.PI / 180);
                int k = 3 * (y * width + x);
                pixels[k] = sun ? 5000f : (float)(0.3 + 0.5 * Math.Max(dy, 0));
                pixels[k + 1] = sun ? 4500f : (float)(0.4 + 0.6 * Math.Max(dy, 0));
                pixels[k + 2] = sun ? 4000f : (float)(0.6 + 0.9 * Math.Max(dy, 0));
            }
        }
        pixels[3 * (60 * width + 7) + 2] = -0.002f;
        return pixels;
    }

    // RGB texels in [0, 2) from a fixed generator: the comparisons are bit for bit, so any
    // values do.
    static float[] Noise(int width, int height, uint seed)
    {
        var pixels = new float[width * height * 3];
        uint state = seed;
        for (int k = 0; k < pixels.Length; ++k)
        {
            state = unchecked(state * 1664525u + 1013904223u);
            pixels[k] = (state >> 8) / (float)(1 << 23);
        }
        return pixels;
    }

    // Portable Float Map: "PF", size, -1 (little-endian), then rows from the bottom up.
    static string WritePfm(string name, float[] pixels, int width, int height)
    {
        string path = Path.Combine(work, name);
        using (var file = new BinaryWriter(File.Create(path)))
        {
            file.Write(Encoding.ASCII.GetBytes("PF\n" + width + " " + height + "\n-1.0\n"));
            for (int y = height - 1; y >= 0; --y)
                for (int k = 0; k < width * 3; ++k) file.Write(pixels[3 * y * width + k]);  // BinaryWriter: little-endian
        }
        return path;
    }

    // `shpack convert <arguments> -o <work>/<output>`; returns the output's path.
    static string RunCli(string arguments, string output)
    {
        string path = Path.Combine(work, output);
        var info = new ProcessStartInfo(cli, "convert " + arguments + " -o \"" + path + "\"") { UseShellExecute = false, RedirectStandardError = true };
        using (Process process = Process.Start(info))
        {
            string err = process.StandardError.ReadToEnd();
            process.WaitForExit();
            if (process.ExitCode != 0) throw new Exception("shpack convert " + arguments + " failed: " + err);
        }
        return path;
    }

    // RGB floats, rows from the top, as Colors in the order Texture2D.GetPixels returns them:
    // rows from the bottom.
    static Color[] BottomUpColors(float[] pixels, int width, int height)
    {
        var colors = new Color[width * height];
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
            {
                int k = 3 * (y * width + x);
                colors[(height - 1 - y) * width + x] = new Color(pixels[k], pixels[k + 1], pixels[k + 2], 1f);
            }
        return colors;
    }

    static int Main(string[] args)
    {
        cli = args[0];
        work = args[1];
        string studioJson = args[2];
        Directory.CreateDirectory(work);
        Check(ShpackNative.IsCompatible(), "the loaded shpack_c has the ABI version of ShpackNative");

        CheckConversions();
        CheckEditor();

        // The command's C# output, compiled into this test, builds the document's probe.
        ShpackProbeData studio = ShpackDocument.ReadFile(studioJson)[0];
        CheckProbe(ShpackStudio.Probe(), studio.UnitySh, "ShpackStudio.Probe()");

        Console.WriteLine(failures == 0 ? "ShpackMonoTest: all checks passed" : "ShpackMonoTest: " + failures + " failures");
        return failures == 0 ? 0 : 1;
    }
}
