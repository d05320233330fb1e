<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/common/data-types.xsl - the model's own data types as every
  target sees them: which UML DataType or Enumeration a typed element names,
  its multiplicity as an array, the attributes a data type or a class has
  with those it inherits (UML Generalization), the data types a package
  needs in the order C++ declares them, and the checks of default values
  against their types. Included by xslt/m2m/common/psm-kit.xsl; a target
  maps what it finds to its own types (xslt/m2m/<target>/psm.xsl).

  Reads:   elements of a bound PIM (urn:robomda:pim:1): typed elements
           (@type, @primitive, @lower, @upper), pim:datatype,
           pim:enumeration, pim:class, pim:generalization.
  Writes:  nothing but values.
  Params:  none.  Keys: fp:id (psm-kit.xsl), fp:feature (here: a classifier's
           attributes and operations, by the classifier).
  Errors:  through f:fail, with the code the caller passes:
           fp:data-types       a data type that contains itself
           fp:default-items    a default with more items than the array holds,
                               or a list for a single value
           fp:enum-literal     a default that names no literal of the enumeration

  Functions
    fp:type-def($typed)        the pim:datatype / pim:enumeration it names, or ()
    fp:array($typed)           () single; ('unbounded'); ('fixed', n); ('bounded', n)
    fp:multiplicity-label($typed)  '' for one value, else '[lower..upper]' (keys, messages)
    fp:lineage($classifier)    the classifier, then its generals, nearest first
    fp:attributes($classifier) its attributes with the inherited ones (general's
                               first; a redefinition by name wins)
    fp:operations($classifier) its operations with the inherited ones (the same)
    fp:data-types($types, $code)   $types (data types, enumerations) and those they use, each after those
                               its attributes use
    fp:default-items($value, $typed, $id, $code)  a default as its items
    fp:enum-literal($value, $enumeration, $id, $code)  the literal a default names
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:type-def" as="element()?">
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="if ($typed/@type) then key('fp:id', $typed/@type, root($typed))[self::pim:datatype or self::pim:enumeration]
                          else ()"/>
  </xsl:function>

  <!-- UML multiplicity [lower..upper] of a value: upper 1 (or none) is one
       value; '*' any number; n with lower n exactly n; else at most n -->
  <xsl:function name="fp:array" as="xs:string*">
    <xsl:param name="typed" as="element()"/>
    <xsl:variable name="upper" as="xs:string" select="normalize-space($typed/@upper)"/>
    <xsl:variable name="lower" as="xs:string" select="(normalize-space($typed/@lower)[. ne ''], '1')[1]"/>
    <xsl:sequence select="
      if ($upper = ('', '1') or not($upper eq '*' or $upper castable as xs:integer)) then ()
      else if ($upper eq '*') then 'unbounded'
      else if (xs:integer($upper) le 1) then ()
      else if ($lower eq $upper) then ('fixed', string(xs:integer($upper)))
      else ('bounded', string(xs:integer($upper)))"/>
  </xsl:function>

  <!-- '[lower..upper]' of a typed element with an upper bound other than
       1, '' otherwise: how connections compare multiplicities and how
       messages show them -->
  <xsl:function name="fp:multiplicity-label" as="xs:string">
    <xsl:param name="typed" as="element()"/>
    <xsl:sequence select="if ($typed/@upper = ('', '1') or empty($typed/@upper)) then ''
                          else '[' || $typed/@lower || '..' || $typed/@upper || ']'"/>
  </xsl:function>

  <!-- the classifier and every classifier it specializes, nearest first
       (the import refuses a cycle of generalizations, IMP021) -->
  <xsl:function name="fp:lineage" as="element()*">
    <xsl:param name="classifier" as="element()"/>
    <xsl:sequence select="$classifier,
        ($classifier/pim:generalization/@general ! key('fp:id', ., root($classifier))) ! fp:lineage(.)"/>
  </xsl:function>

  <!-- the features named $kind (attribute / operation) of a classifier and
       of its generals; for each name the nearest one, in the order the
       generals declare them first (a C++ base class's members come first) -->
  <xsl:function name="fp:features" as="element()*">
    <xsl:param name="classifier" as="element()"/>
    <xsl:param name="kind" as="xs:string"/>
    <xsl:variable name="lineage" as="element()*" select="fp:lineage($classifier)"/>
    <xsl:sequence select="if (count($lineage) eq 1) then fp:own-features($classifier, $kind)
        else for $name in distinct-values(reverse($lineage) ! fp:own-features(., $kind)/@name)
             return ($lineage ! fp:own-features(., $kind)[@name eq $name])[1]"/>
  </xsl:function>

  <!-- the features named $kind of $classifier itself, in document order:
       a look-up, not a scan of its children (a composite holds a part and a
       connector per instance, and every instance asks for its attributes) -->
  <xsl:key name="fp:feature" match="*[local-name() = ('attribute', 'operation')]" use="generate-id(..) || '|' || local-name()"/>
  <xsl:function name="fp:own-features" as="element()*">
    <xsl:param name="classifier" as="element()"/>
    <xsl:param name="kind" as="xs:string"/>
    <xsl:sequence select="if (root($classifier) instance of document-node())
                          then key('fp:feature', generate-id($classifier) || '|' || $kind, root($classifier))
                          else $classifier/*[local-name() eq $kind]"/>
  </xsl:function>

  <xsl:function name="fp:attributes" as="element(pim:attribute)*">
    <xsl:param name="classifier" as="element()"/>
    <xsl:sequence select="fp:features($classifier, 'attribute')"/>
  </xsl:function>

  <xsl:function name="fp:operations" as="element(pim:operation)*">
    <xsl:param name="classifier" as="element()"/>
    <xsl:sequence select="fp:features($classifier, 'operation')"/>
  </xsl:function>

  <!-- ================================================ the types a package needs -->
  <xsl:function name="fp:type-closure" as="element()*">
    <xsl:param name="types" as="element()*"/>
    <xsl:variable name="next" as="element()*"
        select="$types | $types/self::pim:datatype ! fp:attributes(.) ! fp:type-def(.)"/>
    <xsl:sequence select="if (count($next) eq count($types)) then $types else fp:type-closure($next)"/>
  </xsl:function>

  <!-- how many data types deep a type nests; fails on a type that contains
       itself ($path: the ids of the types that contain this one) -->
  <xsl:function name="fp:type-depth" as="xs:integer">
    <xsl:param name="type" as="element()"/>
    <xsl:param name="path" as="element()*"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:sequence select="
      if (some $p in $path satisfies $p is $type)
      then f:fail($code, $type/@id, 'data type ''' || $type/@name || ''' contains itself ('
                  || string-join(($path, $type) ! string(@name), ' > ') || '): no C++ type or message can')
      else if ($type/self::pim:enumeration) then 0
      else max((0, fp:attributes($type) ! fp:type-def(.) ! (1 + fp:type-depth(., ($path, $type), $code))))"/>
  </xsl:function>

  <!-- the data types and enumerations $types, with those their
       attributes name, each after the ones it uses (then by name) -->
  <xsl:function name="fp:data-types" as="element()*">
    <xsl:param name="types" as="element()*"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:perform-sort select="fp:type-closure($types)">
      <xsl:sort select="fp:type-depth(., (), $code)"/>
      <xsl:sort select="string(@name)"/>
      <xsl:sort select="string(@id)"/>
    </xsl:perform-sort>
  </xsl:function>

  <!-- ================================================== default values -->
  <!-- the items of a default: for an array, a list in braces or brackets
       ({1, 2, 3}), or one value (every item of a fixed array has it); a
       list for a single value, or more items than a fixed or bounded array
       holds, fails with $code. Items are not unquoted here. -->
  <xsl:function name="fp:default-items" as="xs:string*">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="typed" as="element()"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:variable name="text" as="xs:string" select="normalize-space($value)"/>
    <xsl:variable name="list" as="xs:boolean" select="matches($text, '^(\{.*\}|\[.*\])$')"/>
    <xsl:variable name="items" as="xs:string*"
        select="if ($list) then tokenize(substring($text, 2, string-length($text) - 2), ',') ! normalize-space(.)[. ne '']
                else $text"/>
    <xsl:variable name="array" as="xs:string*" select="fp:array($typed)"/>
    <xsl:sequence select="
      if (empty($array)) then
        (if ($list) then f:fail($code, $id, 'default ''' || $value || ''' is a list, for a single value') else $items)
      else if ($array[1] eq 'unbounded' or count($items) le xs:integer($array[2])) then
        (if ($array[1] eq 'fixed' and not($list)) then (1 to xs:integer($array[2])) ! $items else $items)
      else f:fail($code, $id, 'default ''' || $value || ''' has ' || count($items) || ' values, the array at most '
                  || $array[2])"/>
  </xsl:function>

  <!-- the literal of $enumeration a default names (by name, also as
       Type::LITERAL or Type.LITERAL) -->
  <xsl:function name="fp:enum-literal" as="element()">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="enumeration" as="element(pim:enumeration)"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:param name="code" as="xs:string"/>
    <xsl:variable name="name" as="xs:string" select="replace(f:unquote(normalize-space($value)), '^.*(::|\.)', '')"/>
    <xsl:sequence select="($enumeration/pim:literal[@name eq $name],
        f:fail($code, $id, 'default ''' || $value || ''' is no literal of enumeration ''' || $enumeration/@name
               || ''' (' || string-join($enumeration/pim:literal/@name, ', ') || ')'))[1]"/>
  </xsl:function>
</xsl:stylesheet>
