// UnityEditor.cs - a stub of the UnityEditor members the shpack package's editor scripts use,
// so they compile under Mono; see UnityEngine.cs. Undo, dialogs, the asset database and the
// scene's dirty flag record what they are given, for the test to check.
using System;
using System.Collections.Generic;
using UnityEngine;

namespace UnityEditor
{
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class MenuItem : Attribute
    {
        public MenuItem(string itemName) { }
        public MenuItem(string itemName, bool isValidateFunction) { }
    }

    public static class EditorUtility
    {
        public static bool Answer = true;  // what the user clicks: ok (true) or cancel
        public static readonly List<string> Dialogs = new List<string>();

        public static string OpenFilePanel(string title, string directory, string extension) { return ""; }
        public static string SaveFilePanelInProject(string title, string defaultName, string extension, string message) { return ""; }
        public static bool DisplayDialog(string title, string message, string ok) { Dialogs.Add(message); return true; }
        public static bool DisplayDialog(string title, string message, string ok, string cancel) { Dialogs.Add(message); return Answer; }
    }

    public static class Selection
    {
        public static UnityEngine.Object activeObject;
    }

    public static class Undo
    {
        public static readonly List<string> Log = new List<string>();  // "record <name>", "create <name>", ...
        static int group;

        public static void RecordObject(UnityEngine.Object objectToUndo, string name) { Log.Add("record " + objectToUndo.GetType().Name); }
        public static void RegisterCreatedObjectUndo(UnityEngine.Object objectToUndo, string name) { Log.Add("create " + objectToUndo.name); }
        public static void DestroyObjectImmediate(UnityEngine.Object objectToUndo)
        {
            Log.Add("destroy " + objectToUndo.name);
            UnityEngine.Object.DestroyImmediate(objectToUndo);
        }
        public static T AddComponent<T>(GameObject gameObject) where T : Component
        {
            Log.Add("add " + typeof(T).Name);
            return gameObject.AddComponent<T>();
        }
        public static int GetCurrentGroup() { return group; }
        public static void SetCurrentGroupName(string name) { Log.Add("group " + name); }
        public static void CollapseUndoOperations(int groupIndex) { ++group; }
    }

    public static class AssetDatabase
    {
        public static readonly Dictionary<string, UnityEngine.Object> Assets = new Dictionary<string, UnityEngine.Object>();

        public static void CreateAsset(UnityEngine.Object asset, string path) { Assets[path] = asset; }
        public static void SaveAssets() { }
    }
}

namespace UnityEditor.SceneManagement
{
    public static class EditorSceneManager
    {
        public static int DirtyMarks;

        public static bool MarkSceneDirty(UnityEngine.SceneManagement.Scene scene) { ++DirtyMarks; return true; }
    }
}
