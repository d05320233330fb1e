<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/common/data-types.xsl - the C++ header of a model's data type or
  enumeration, the same for every target: include/<Name>.hpp declares, in
  the namespaces of its @cpp-name (::<pkg>::types::<Name>, m2m psm-kit.xsl
  fp:type-cpp-name), struct <Name> (its attributes, inherited ones first,
  as members initialised to the model's defaults) or enum <Name>; with
  ROBOMDA_GLOBAL_TYPE_NAMES defined, also a global using-declaration of
  it (after the include guard: a using-declaration may be repeated). The atomic code includes it by that name too (the generated
  package's include/ directory comes first on the include path of the
  atomic-code library).

  Reads:   a PSM's type definitions, of any target's namespace: an element
           with @cpp-name and @header, holding *:field elements (a struct:
           @member, @cpp-type, @cpp-default, optional @type-ref, @type-kind,
           @include: a header its type needs)
           or *:literal elements (an enumeration: @member).
  Writes:  strings (file contents).
  Params:  none.  Errors: none.
  Keys:    fp:type-definition (a type definition by @xmi-id).
  Uses:    fp:lines, fp:banner, fp:doc-of (text.xsl).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- the definitions among $definitions (siblings, in document order) with
       an @xmi-id of $ids, in document order: a look-up, not a scan of every
       definition for every type -->
  <xsl:key name="fp:type-definition" match="*[@xmi-id][@header]" use="@xmi-id"/>
  <xsl:function name="fp:definitions-of" as="element()*">
    <xsl:param name="ids" as="attribute()*"/>
    <xsl:param name="definitions" as="element()*"/>
    <xsl:sequence select="if (empty($definitions) or not(root($definitions[1]) instance of document-node()))
                          then $definitions[@xmi-id = $ids]
                          else key('fp:type-definition', $ids, root($definitions[1]))[.. is $definitions[1]/..]"/>
  </xsl:function>

  <!-- the header of type $type; $definitions: every type definition of the
       package (the headers of the types its fields use) -->
  <xsl:function name="fp:type-header" as="xs:string">
    <xsl:param name="type" as="element()"/>
    <xsl:param name="definitions" as="element()*"/>
    <xsl:param name="model-name" as="xs:string"/>
    <xsl:variable name="parts" as="xs:string+" select="tokenize($type/@cpp-name, '::')[. ne '']"/>
    <xsl:variable name="name" as="xs:string" select="$parts[last()]"/>
    <xsl:variable name="namespaces" as="xs:string*" select="$parts[position() lt last()]"/>
    <xsl:variable name="guard" as="xs:string" select="fp:path-guard($type/@header)"/>
    <xsl:variable name="enum" as="xs:boolean" select="exists($type/*:literal)"/>
    <xsl:variable name="fields" as="element()*" select="$type/*:field"/>
    <xsl:variable name="includes" as="xs:string*" select="
        if ($fields[@type-kind eq 'sequence']) then '#include &lt;vector&gt;' else (),
        if ($fields[contains(@cpp-type, 'std::string')]) then '#include &lt;string&gt;' else (),
        distinct-values($fields/@include) ! ('#include &lt;' || . || '&gt;'),
        distinct-values(fp:definitions-of($fields/@type-ref, $definitions)/@header) ! ('#include &quot;' || . || '&quot;')"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', 'm2t/common/data-types.xsl', (if ($enum) then 'enumeration ''' else 'data type ''') || $type/@name
                  || ''' of model ''' || $model-name || '''', false()),
        '#ifndef ' || $guard,
        '#define ' || $guard,
        '',
        $includes, if (exists($includes)) then '' else (),
        $namespaces ! ('namespace ' || ., '{'), if (exists($namespaces)) then '' else (),
        '/** ' || fp:doc-of($type, (if ($enum) then 'Enumeration ' else 'Data type ') || $type/@name || ' of the model.') || ' */',
        if ($enum) then (
          'enum ' || $name,
          '{',
          $type/*:literal ! ('  ' || @member || (if (position() eq last()) then '' else ',')),
          '};')
        else (
          'struct ' || $name,
          '{',
          $fields ! ('  ' || @cpp-type || ' ' || @member || ' = ' || @cpp-default || ';'
                     || (if (*:doc) then '  // ' || normalize-space(*:doc) else '')),
          '};'),
        if (exists($namespaces)) then ('', reverse($namespaces) ! ('}  // namespace ' || .)) else (),
        '',
        '#endif  // ' || $guard,
        if (exists($namespaces)) then (
          '',
          '// Code written for the global name (atomic code that one package and another',
          '// both build) defines ROBOMDA_GLOBAL_TYPE_NAMES before it includes this header;',
          '// outside the include guard, so that it holds after an earlier include too (and',
          '// so not the last #endif cpplint takes for the guard''s: NOLINT on that line only).',
          '#ifdef ROBOMDA_GLOBAL_TYPE_NAMES',
          'using ' || $type/@cpp-name || ';',
          '#endif  // ROBOMDA_GLOBAL_TYPE_NAMES NOLINT(build/header_guard)')
        else ()))"/>
  </xsl:function>
</xsl:stylesheet>
