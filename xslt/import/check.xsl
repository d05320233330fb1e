<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/check.xsl - the reference checks of the XMI import.

  Reads:   the normalised XMI.
  Writes:  nothing; fp:problems describes what is wrong with one element,
           import.xsl raises the first problem in document order (so the
           reported element does not depend on the engine's evaluation
           order). fp:any-dangling-ids tells in one pass whether any
           element can have a dangling reference, so a sound model (the
           common case) calls fp:problems only for its Generalizations.
  Params:  none.
  Errors:  the descriptions of IMP010-IMP021 (codes documented in
           import.xsl). A reference is dangling when it is an id that no
           element of the file (outside xmi:Extension) carries and that is
           not a tool built-in type (EAJava_int ...). An href into another
           file is never dangling. A relationship robomda would not import
           whatever its missing ends are (its clients in the file, or its
           suppliers, are none of a classifier, port, protocol or EA
           exposed interface: fp:unused-anyway) is not checked: a partial
           export leaves such ends out, and report.xsl names it (IMP112).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:x="urn:robomda:import:xmi"
    exclude-result-prefixes="#all">

  <!-- which references of which metaclass are checked, with the code -->
  <xsl:variable name="checked-references" as="map(xs:string, map(*))" select="map {
      'Property':             map { 'code': 'IMP010', 'refs': ('type') },
      'Parameter':            map { 'code': 'IMP010', 'refs': ('type') },
      'Port':                 map { 'code': 'IMP011', 'refs': ('type') },
      'Generalization':       map { 'code': 'IMP012', 'refs': ('general') },
      'ComponentRealization': map { 'code': 'IMP013', 'refs': ('realizingClassifier', 'client', 'supplier') },
      'Realization':          map { 'code': 'IMP013', 'refs': ('client', 'supplier') },
      'InterfaceRealization': map { 'code': 'IMP014', 'refs': ('client', 'supplier', 'contract') },
      'Usage':                map { 'code': 'IMP015', 'refs': ('client', 'supplier') },
      'Deployment':           map { 'code': 'IMP016', 'refs': ('client', 'supplier', 'deployedArtifact', 'location') },
      'Manifestation':        map { 'code': 'IMP017', 'refs': ('client', 'supplier', 'utilizedElement') },
      'ConnectorEnd':         map { 'code': 'IMP018', 'refs': ('role', 'partWithPort') },
      'CommunicationPath':    map { 'code': 'IMP019', 'refs': ('memberEnd') },
      'Dependency':           map { 'code': 'IMP020', 'refs': ('client', 'supplier') }
    }"/>

  <!-- every property name of $checked-references (the keys) -->
  <xsl:variable name="checked-properties" as="map(xs:string, xs:boolean)"
      select="map:merge(distinct-values($checked-references?*?refs) ! map:entry(., true()))"/>

  <!-- the ids that the elements $checked (of a metaclass of
       $checked-references) reference by any checked property name, and
       that are dangling: empty when fp:problems finds no dangling
       reference in $checked (a superset of the ids it would report, in
       one pass instead of a call per element and property) -->
  <xsl:function name="fp:any-dangling-ids" as="xs:string*">
    <xsl:param name="checked" as="element()*"/>
    <!-- an id several files use (files.xsl) is resolved in the file of
         its reference, not of $checked[1]: always in the superset -->
    <xsl:variable name="ids" as="xs:string*" select="distinct-values(
        $checked/(@Q{}*[map:contains($checked-properties, local-name())]/tokenize(.),
                  Q{}*[map:contains($checked-properties, local-name())]/@x:idref/string()))"/>
    <xsl:sequence select="$checked[1] ! (fp:dangling-ids(., $ids), $ids[exists(key('fp:shared-id', ., root($checked[1])))])"/>
  </xsl:function>

  <!-- the problems of one element: maps with code, id, message -->
  <xsl:function name="fp:problems" as="map(*)*">
    <xsl:param name="element" as="element()"/>
    <xsl:variable name="meta" as="xs:string" select="fp:meta($element)"/>
    <!-- a plain Dependency is checked only when it is a deployment-sequence
         constraint (StartAfter): every other one is not imported -->
    <!-- nor is a relationship that robomda would not import whatever its
         missing ends are (a Realization between packages in a partial
         export): report.xsl names it and its missing ends (IMP112) -->
    <xsl:variable name="rule" as="map(*)?"
        select="if ($meta eq 'Dependency' and not(fp:is-start-after($element))) then ()
                else if (fp:unused-anyway($element, $meta)) then ()
                else $checked-references($meta)"/>
    <xsl:if test="exists($rule)">
      <xsl:for-each select="$rule?refs">
        <xsl:variable name="prop" as="xs:string" select="."/>
        <xsl:for-each select="fp:dangling-ids($element, fp:ref-ids($element, $prop))">
          <xsl:sequence select="map {
              'code': $rule?code,
              'id': fp:id($element),
              'message': fp:describe($element) || ' refers by ' || $prop || ' to ''' || . ||
                         ''', which is not in the model' ||
                         (if ($meta eq 'Port') then ' (the port''s interface or class is missing)' else '')
            }"/>
        </xsl:for-each>
      </xsl:for-each>
    </xsl:if>
    <xsl:if test="$meta eq 'Generalization' and fp:generalizes-itself($element)">
      <xsl:sequence select="map {
          'code': 'IMP021',
          'id': fp:id($element),
          'message': fp:describe($element) || ' makes ' || fp:label($element/..) || ' a specialization of itself'
                     || ' (cyclic generalization through ' || string-join(fp:targets($element, 'general') ! fp:label(.), ', ')
                     || '): remove one generalization of the cycle'
        }"/>
    </xsl:if>
  </xsl:function>

  <!-- true when $rel (a Usage, Realization, InterfaceRealization or
       ComponentRealization) has clients in the file and none robomda can
       use as one, or suppliers in the file and none it can use as one
       (a package, a comment, a use case ...): it is not imported, whatever
       its references that are not in the file would be -->
  <xsl:function name="fp:unused-anyway" as="xs:boolean">
    <xsl:param name="rel" as="element()"/>
    <xsl:param name="meta" as="xs:string"/>
    <xsl:variable name="clients" as="element()*" select="fp:targets($rel, 'client')"/>
    <xsl:variable name="suppliers" as="element()*" select="fp:targets($rel, 'supplier')"/>
    <xsl:sequence select="$meta = ('Usage', 'Realization', 'InterfaceRealization', 'ComponentRealization')
        and ((exists($clients) and (every $c in $clients satisfies not(fp:usable-end($c))))
             or (exists($suppliers) and (every $s in $suppliers satisfies not(fp:usable-end($s)))))"/>
  </xsl:function>

  <!-- an element robomda can read at an end of a Usage or Realization: a
       classifier, port or protocol it imports, or an EA exposed interface -->
  <xsl:function name="fp:usable-end" as="xs:boolean">
    <xsl:param name="end" as="element()"/>
    <xsl:sequence select="fp:meta($end) = ('Class', 'Component', 'Interface', 'Port', 'Collaboration')
                          or local-name($end) = ('provided', 'required')"/>
  </xsl:function>

  <!-- true when going up the generalizations from the general of $g comes
       back to the classifier that owns $g -->
  <xsl:function name="fp:generalizes-itself" as="xs:boolean">
    <xsl:param name="group" as="element()"/>
    <xsl:sequence select="fp:reaches(fp:targets($group, 'general'), $group/.., ())"/>
  </xsl:function>

  <!-- breadth-first up the generalizations, each classifier visited once -->
  <xsl:function name="fp:reaches" as="xs:boolean">
    <xsl:param name="front" as="element()*"/>
    <xsl:param name="target" as="element()"/>
    <xsl:param name="seen" as="element()*"/>
    <xsl:sequence select="
        if (empty($front)) then false()
        else if (some $c in $front satisfies $c is $target) then true()
        else fp:reaches(($front/*[fp:meta(.) eq 'Generalization'] ! fp:targets(., 'general'))
                          except ($seen | $front), $target, $seen | $front)"/>
  </xsl:function>

  <!-- "Property 'speed' of Class 'Arm'" -->
  <xsl:function name="fp:describe" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:variable name="owner" as="element()?" select="$element/ancestor::*[@name][1]"/>
    <xsl:sequence select="fp:label($element) ||
        (if ($owner) then ' of ' || fp:label($owner) else '')"/>
  </xsl:function>
</xsl:stylesheet>
