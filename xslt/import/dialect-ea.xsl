<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/dialect-ea.xsl - Enterprise Architect quirks (XMI 2.1 / 2.4.1).

  Reads:   the normalised XMI (see xmi-common.xsl).
  Writes:  nothing itself; functions used by the application and platform
           rules.
  Params:  none.
  Errors:  none.

  Rules
  - Model root: EA wraps the project in <uml:Model name="EA_Model"> without
    xmi:id around the root package. When the model element has no xmi:id
    and holds exactly one packaged element, a package, that package is the
    model root (its name, id and the start of every qualified name), so the
    same model exported by Papyrus and by EA gives the same PIM.
  - Built-in types: ids such as EAJava_int, EAnone_double have no element in
    the file (EA defines them, if at all, inside xmi:Extension); the
    prefixes and libraries are data in xslt/common/primitive-types.xml
    (tool-id), read by fp:builtin-library in xmi-common.xsl.
  - Exposed interfaces: EA writes a component's or port's provided and
    required interfaces as child elements <provided xmi:id=".." xmi:idref=
    "INTERFACE"/> and <required .../>; the xmi:idref names the interface
    (absent when the exposed interface is not classified; an xmi:type
    uml:Interface on it does not make it an interface of its own). A Usage or
    Dependency may connect such exposed elements; fp:interface-of sees
    through them to the interface. An exposed element without xmi:idref
    (EA leaves it unclassified) or naming no interface is not an
    interface, even with xmi:type uml:Interface (application.xsl leaves it
    out of the packageable elements); report.xsl names it (IMP119).
  - Component realization: EA writes a generic uml:Realization from the
    realizing class (client) to the component (supplier).
  - Dependencies between parts (a deployment-sequence StartAfter): a
    packagedElement xmi:type="uml:Dependency" in the package of the source
    element, client and supplier as attributes; the stereotype is applied
    the standard way (a top-level robomda:StartAfter with base_Dependency,
    no xmi:id) and repeated in the xmi:Extension connector properties
    (stereotype="StartAfter"), which is ignored like the rest of the
    extension. Nothing dialect-specific is needed (application.xsl).
  - Tool: xmi:Documentation exporter "Enterprise Architect", the Sparx
    profile namespaces, or EAID_/EAPK_ ids.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:u="urn:robomda:import:uml"
    xmlns:x="urn:robomda:import:xmi"
    exclude-result-prefixes="#all">

  <!-- the element the PIM model stands for -->
  <xsl:function name="fp:model-root" as="element()">
    <xsl:param name="model" as="element()"/>
    <xsl:variable name="packaged" as="element()*" select="$model/packagedElement"/>
    <xsl:sequence select="
        if (empty($model/@x:id) and count($packaged) eq 1
            and fp:meta($packaged) = ('Package', 'Model'))
        then $packaged else $model"/>
  </xsl:function>

  <!-- EA exposed interfaces of a classifier or port: $which is 'provided'
       or 'required'; the elements carry the xmi:idref of the interface -->
  <xsl:function name="fp:exposed" as="element()*">
    <xsl:param name="element" as="element()"/>
    <xsl:param name="which" as="xs:string"/>
    <xsl:sequence select="$element/*[local-name() eq $which][namespace-uri() eq ''][@x:idref]"/>
  </xsl:function>

  <!-- the interface an element stands for: itself when an Interface, the
       classifier of an EA exposed interface -->
  <xsl:function name="fp:interface-of" as="element()?">
    <xsl:param name="element" as="element()?"/>
    <xsl:sequence select="
        if (empty($element)) then ()
        else if (local-name($element) = ('provided', 'required') and $element/@x:idref)
          then fp:element($element, $element/@x:idref)[@x:type eq 'Interface']
        else if (fp:meta($element) eq 'Interface') then $element
        else ()"/>
  </xsl:function>

  <!-- generic Realizations whose supplier is the component $c and whose
       client is a class or component: EA's component realization -->
  <xsl:function name="fp:ea-realizations" as="element()*">
    <xsl:param name="classifier" as="element()"/>
    <xsl:sequence select="key('fp:dep-by-supplier', fp:id($classifier), root($classifier))[@x:type eq 'Realization']
                          [some $t in fp:targets(., 'client') satisfies fp:meta($t) = ('Class', 'Component')]"/>
  </xsl:function>

  <!-- $marked-id: the first id of $doc that looks like an EA or a StarUML
       one (fp:marked-id of import.xsl), so that a file without such ids
       is not scanned again here -->
  <xsl:function name="fp:is-ea" as="xs:boolean">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="exporter" as="xs:string"/>
    <xsl:param name="marked-id" as="xs:string?"/>
    <xsl:sequence select="contains(lower-case($exporter), 'enterprise architect')
        or (not($exporter) and (
              some $ns in $doc/*/namespace::* satisfies contains($ns, 'sparxsystems')
              or starts-with($marked-id, 'EA')
              or (exists($marked-id)
                  and exists(($doc/*//@*:id[starts-with(., 'EAID_') or starts-with(., 'EAPK_')])[1]))))"/>
  </xsl:function>
</xsl:stylesheet>
