<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/common/user-class.xsl - the user's class of a component without a
  realizing class, on every C++ target (Orocos, ROS 1, ROS 2, OpenRTM).

  Reads:   any PSM element of a component with @xmi-id and @name (o:task-
           context, r:node, OpenRTM's r:component).
  Writes:  fs:file elements of mode "user" (schemas/fileset/1/fileset.xsd)
           and the frames of the user's header and source (strings).
  Params:  none.  Errors: none.
  Uses:    fp:banner, fp:guard, fp:lines, fp:what of common/text.xsl
           (included by each target's main.xsl).

  A file of the user's is written once and never overwritten
  (src/robomda/output.py); its fs:file says which model element it
  implements (@implements, @implements-name: a rename or removal stops the
  run, OUT003) and what the generated base requires of it (@signature, one
  item per port, operation, hook, ...: a change is warning OUT004). The
  class derives from the generated base, whose hooks it overrides: a hook
  the model no longer has is gone from the base, so its "override" stops
  the build instead of leaving dead code in silence.

    fp:user-class-file($path, $stylesheet, $component, $signature, $text)
    fp:user-class-header($stylesheet, $component, $namespace, $class, $base, $body, $extension, $trailer)
    fp:user-class-source($stylesheet, $component, $namespace, $class, $body, $extension, $trailer)
      $extension: the headers' ('.hpp'; OpenRTM '.h'); $trailer: lines after
      the namespace (OpenRTM's module entry <Class>Init; () elsewhere)
    fp:definition($head, $body)   "head { body }" on lines of their own
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- a user file of $component: what it implements and what the
       generated base requires of it ($signature, one item each) -->
  <xsl:function name="fp:user-class-file" as="element(fs:file)">
    <xsl:param name="path" as="xs:string"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:param name="component" as="element()"/>
    <xsl:param name="signature" as="xs:string*"/>
    <xsl:param name="text" as="xs:string"/>
    <fs:file path="{$path}" mode="user" stylesheet="{$stylesheet}" implements="{$component/@xmi-id}"
             implements-name="{$component/@name}" signature="{string-join($signature, '; ')}">
      <xsl:value-of select="$text"/>
    </fs:file>
  </xsl:function>

  <!-- the user's header: class $class of $namespace deriving from $base
       (<$namespace/$base$extension>), with the lines $body between its
       braces and the lines $trailer after the namespace (a declaration
       outside it: OpenRTM's module entry) -->
  <xsl:function name="fp:user-class-header" as="xs:string">
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:param name="component" as="element()"/>
    <xsl:param name="namespace" as="xs:string"/>
    <xsl:param name="class" as="xs:string"/>
    <xsl:param name="base" as="xs:string"/>
    <xsl:param name="body" as="xs:string*"/>
    <xsl:param name="extension" as="xs:string"/>
    <xsl:param name="trailer" as="xs:string*"/>
    <xsl:variable name="guard" as="xs:string" select="fp:guard($namespace, $class)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $stylesheet, fp:what($component), true()),
        concat('#ifndef ', $guard),
        concat('#define ', $guard),
        '',
        concat('#include &lt;', $namespace, '/', $base, $extension, '&gt;'),
        '',
        concat('namespace ', $namespace), '{',
        '',
        concat('class ', $class, ' : public ', $base),
        '{',
        $body,
        '};',
        '',
        concat('}  // namespace ', $namespace),
        '',
        if (exists($trailer)) then ($trailer, '') else (),
        concat('#endif  // ', $guard)))"/>
  </xsl:function>

  <!-- the user's source: the definitions $body of class $class, then the
       lines $trailer after the namespace; $extension: its header's -->
  <xsl:function name="fp:user-class-source" as="xs:string">
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:param name="component" as="element()"/>
    <xsl:param name="namespace" as="xs:string"/>
    <xsl:param name="class" as="xs:string"/>
    <xsl:param name="body" as="xs:string*"/>
    <xsl:param name="extension" as="xs:string"/>
    <xsl:param name="trailer" as="xs:string*"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $stylesheet, fp:what($component), true()),
        concat('#include &lt;', $namespace, '/', $class, $extension, '&gt;'),
        '',
        concat('namespace ', $namespace), '{',
        '',
        $body,
        '',
        concat('}  // namespace ', $namespace),
        if (exists($trailer)) then ('', $trailer) else ()))"/>
  </xsl:function>

  <!-- a function's definition: $head, then $body in braces -->
  <xsl:function name="fp:definition" as="xs:string+">
    <xsl:param name="head" as="xs:string"/>
    <xsl:param name="body" as="xs:string*"/>
    <xsl:sequence select="$head, '{', $body, '}'"/>
  </xsl:function>
</xsl:stylesheet>
