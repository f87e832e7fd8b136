// UnityEditor.cs - a stub of the UnityEditor members the shpack package's editor script uses
// (MenuItem, EditorUtility), so it compiles under Mono; see UnityEngine.cs.
using System;

namespace UnityEditor
{
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class MenuItem : Attribute
    {
        public MenuItem(string itemName) { }
    }

    public static class EditorUtility
    {
        public static string OpenFilePanel(string title, string directory, string extension) { return ""; }
        public static bool DisplayDialog(string title, string message, string ok) { Console.Error.WriteLine(message); return true; }
    }
}
