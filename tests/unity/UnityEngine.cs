// UnityEngine.cs - a stub of the UnityEngine types the shpack Unity package uses, so the
// package compiles and runs under Mono without Unity (tests/unity/run_mono_test.cmake). Only
// the members the package touches, with Unity's names and signatures (Unity Scripting API);
// SphericalHarmonicsL2 keeps Unity's value semantics and its [rgb, coefficient] indexer over
// 27 floats (UnityCsReference, Runtime/Export/Math/SphericalHarmonicsL2.bindings.cs). Not a
// model of Unity's behaviour beyond storing what is assigned. Objects, components and
// textures are in UnityEngineObjects.cs and UnityEngineTextures.cs.
using System;

namespace UnityEngine
{
    public struct Vector3
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        public float sqrMagnitude { get { return x * x + y * y + z * z; } }
        public static Vector3 operator -(Vector3 a, Vector3 b) { return new Vector3(a.x - b.x, a.y - b.y, a.z - b.z); }
    }

    public struct Quaternion
    {
        public float x, y, z, w;
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
    }

    // Four floats, as Unity lays a Color out in memory (GetPixels arrays are read in place).
    public struct Color
    {
        public float r, g, b, a;
        public Color(float r, float g, float b, float a) { this.r = r; this.g = g; this.b = b; this.a = a; }
        public Color(float r, float g, float b) : this(r, g, b, 1f) { }
    }

    public static class Debug
    {
        public static string LastLog, LastWarning;
        public static void Log(object message) { LastLog = message.ToString(); Console.WriteLine(message); }
        public static void LogWarning(object message) { LastWarning = message.ToString(); Console.WriteLine(message); }
    }

    // Unity's RenderSettings is an Object whose per-scene instance only the engine reaches
    // (the internal GetRenderSettings); the static members are its fields.
    public sealed class RenderSettings : Object
    {
        static readonly RenderSettings instance = new RenderSettings();
        RenderSettings() { }
        internal static Object GetRenderSettings() { return instance; }
        public static Rendering.AmbientMode ambientMode;
        public static Rendering.SphericalHarmonicsL2 ambientProbe;
    }

    public sealed class LightProbes : Object
    {
        Vector3[] positions_;
        Rendering.SphericalHarmonicsL2[] baked_;
        // Unity makes these only by baking; the test makes them with positions.
        public LightProbes(Vector3[] positions) { positions_ = positions; baked_ = new Rendering.SphericalHarmonicsL2[positions.Length]; }
        public int count { get { return positions_.Length; } }
        // Unity returns copies of its arrays; so does the stub.
        public Vector3[] positions { get { return (Vector3[])positions_.Clone(); } }
        public Rendering.SphericalHarmonicsL2[] bakedProbes
        {
            get { return (Rendering.SphericalHarmonicsL2[])baked_.Clone(); }
            set { baked_ = (Rendering.SphericalHarmonicsL2[])value.Clone(); }
        }
        internal override Object Copy() { return new LightProbes(positions) { bakedProbes = baked_ }; }
    }

    public static class LightmapSettings
    {
        public static LightProbes lightProbes;
    }
}

namespace UnityEngine.SceneManagement
{
    public struct Scene { }

    public static class SceneManager
    {
        public static Scene GetActiveScene() { return new Scene(); }
    }
}

namespace UnityEngine.Rendering
{
    public enum AmbientMode { Skybox = 0, Trilight = 1, Flat = 3, Custom = 4 }

    public struct SphericalHarmonicsL2
    {
        float shr0, shr1, shr2, shr3, shr4, shr5, shr6, shr7, shr8;
        float shg0, shg1, shg2, shg3, shg4, shg5, shg6, shg7, shg8;
        float shb0, shb1, shb2, shb3, shb4, shb5, shb6, shb7, shb8;

        public float this[int rgb, int coefficient]
        {
            get
            {
                switch (rgb * 9 + coefficient)
                {
                    case 0: return shr0;
                    case 1: return shr1;
                    case 2: return shr2;
                    case 3: return shr3;
                    case 4: return shr4;
                    case 5: return shr5;
                    case 6: return shr6;
                    case 7: return shr7;
                    case 8: return shr8;
                    case 9: return shg0;
                    case 10: return shg1;
                    case 11: return shg2;
                    case 12: return shg3;
                    case 13: return shg4;
                    case 14: return shg5;
                    case 15: return shg6;
                    case 16: return shg7;
                    case 17: return shg8;
                    case 18: return shb0;
                    case 19: return shb1;
                    case 20: return shb2;
                    case 21: return shb3;
                    case 22: return shb4;
                    case 23: return shb5;
                    case 24: return shb6;
                    case 25: return shb7;
                    case 26: return shb8;
                    default: throw new IndexOutOfRangeException("Invalid index!");
                }
            }
            set
            {
                switch (rgb * 9 + coefficient)
                {
                    case 0: shr0 = value; break;
                    case 1: shr1 = value; break;
                    case 2: shr2 = value; break;
                    case 3: shr3 = value; break;
                    case 4: shr4 = value; break;
                    case 5: shr5 = value; break;
                    case 6: shr6 = value; break;
                    case 7: shr7 = value; break;
                    case 8: shr8 = value; break;
                    case 9: shg0 = value; break;
                    case 10: shg1 = value; break;
                    case 11: shg2 = value; break;
                    case 12: shg3 = value; break;
                    case 13: shg4 = value; break;
                    case 14: shg5 = value; break;
                    case 15: shg6 = value; break;
                    case 16: shg7 = value; break;
                    case 17: shg8 = value; break;
                    case 18: shb0 = value; break;
                    case 19: shb1 = value; break;
                    case 20: shb2 = value; break;
                    case 21: shb3 = value; break;
                    case 22: shb4 = value; break;
                    case 23: shb5 = value; break;
                    case 24: shb6 = value; break;
                    case 25: shb7 = value; break;
                    case 26: shb8 = value; break;
                    default: throw new IndexOutOfRangeException("Invalid index!");
                }
            }
        }
    }
}
