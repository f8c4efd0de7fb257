// Stand-in for UnityEngine.DefaultExecutionOrder (script execution order by attribute).
namespace UnityEngine
{
    // UnityCsReference Runtime/Export/Scripting/Attributes.cs: public class DefaultExecutionOrder : Attribute, ctor (int order), int order { get; }.
    [System.AttributeUsage(System.AttributeTargets.Class)]
    public class DefaultExecutionOrder : System.Attribute
    {
        public DefaultExecutionOrder(int order) { this.order = order; }
        public int order { get; }
    }
}
