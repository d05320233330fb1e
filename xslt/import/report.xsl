<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/report.xsl - nothing dropped in silence: the warnings about
  what the import leaves out.

  Reads:   the normalised XMI and the PIM import.xsl made of it.
  Writes:  nothing; warnings (f:warn, "warning: CODE: message [xmi:id=ID]")
           about every element of a kind robomda understands that the PIM
           does not record, and about a model that holds nothing robomda
           generates from.
  Params:  none.
  Errors:  none raised. Warnings (docs/errors.md):
    IMP030  the model holds nothing robomda generates from (no component,
            class, interface or node reaches the PIM); names what it holds,
            leaving out the contents of the profiles it defines.
    IMP110  a connector that is not imported (an end in another file, fewer
            than two ends in the model, no class or component owns the
            parts it joins, the path of parts of a nested end cannot be
            followed: connector-ends.xsl).
    IMP111  a Dependency or Abstraction that is not imported (only a
            deployment-sequence StartAfter one means something; or such a
            one without client or supplier in the model).
    IMP112  a Usage, Realization, InterfaceRealization or
            ComponentRealization that is not imported (its client is not an
            imported classifier or port, or its supplier not an interface /
            the classifier it should be); or one of several clients or
            suppliers that is imported for some of them only (those it is
            not imported for are named).
    IMP113  a Deployment or Manifestation that is not imported (it deploys
            or manifests nothing in the model, or is not on a node /
            artifact).
    IMP114  a CommunicationPath that does not join two nodes.
    IMP115  a stereotype application whose element is not imported (those
            on no element of the model: one warning per stereotype, naming
            them all with xmi:ids=ID,ID...).
    IMP118  an imported element that is a template (owns a template
            signature) or binds one: imported with its own features only;
            the parameters' placeholders (ownedParameteredElement,
            ownedDefault, ownedActual) are not elements of the model.
    IMP119  an Enterprise Architect exposed interface (<provided> /
            <required> of a component, class or port) that names no
            interface of the model.
    IMP116  any other element of a kind robomda reads (component, class,
            interface, port, property, operation, node, artifact) in a place
            the import does not read, or outside the model it reads.

  What counts (the same set tests/xmi_invariant.py checks): every element
  with an xmi:id of metaclass Component, Class, Interface, Node, Device,
  ExecutionEnvironment, Artifact, DeploymentSpecification, Port,
  Connector, CommunicationPath, Dependency, Usage, Realization,
  InterfaceRealization, ComponentRealization, Abstraction, Deployment,
  Manifestation, and Property / Operation owned by a class, component,
  interface, data type, signal, node or artifact (association ends are
  the association's, not counted); outside profiles and xmi:Extension; not
  a reference (href, xmi:idref); EA's exposed interfaces (<provided>,
  <required> of a component, class or port: recorded by the pim:provides /
  pim:requires or the port's @via that names them); the roles (properties)
  and operations of a Collaboration; and every stereotype application with
  an xmi:id. It is recorded when an
  @id or @via of the PIM carries its xmi:id.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:u="urn:robomda:import:uml"
    xmlns:x="urn:robomda:import:xmi"
    xmlns:pim="urn:robomda:pim:1"
    exclude-result-prefixes="#all">

  <xsl:variable name="classifier-metas" as="xs:string+"
      select="('Component', 'Class', 'Interface', $node-metas, $artifact-metas)"/>
  <xsl:variable name="relationship-metas" as="xs:string+"
      select="('Dependency', 'Abstraction', $dependency-metas)"/>
  <xsl:variable name="understood-metas" as="xs:string+"
      select="($classifier-metas, $relationship-metas, 'Port', 'Property', 'Operation', 'Connector',
               'CommunicationPath')"/>
  <xsl:variable name="understood-map" as="map(xs:string, xs:boolean)"
      select="map:merge(distinct-values($understood-metas) ! map:entry(., true()))"/>
  <!-- the owners of the properties and operations that count: a
       Collaboration's are its roles (an interaction's context), which the
       PIM does not hold (IMP116) -->
  <xsl:variable name="feature-owner-map" as="map(xs:string, xs:boolean)"
      select="map:merge(($classifier-metas, 'DataType', 'Signal', 'Collaboration') ! map:entry(., true()))"/>
  <!-- what EA's exposed interfaces belong to -->
  <xsl:variable name="exposing-metas" as="xs:string+" select="('Component', 'Class', 'Port')"/>

  <!-- every id the PIM records -->
  <!-- every id the PIM records: ids, vias, and the relationship a derived
       id stands for (fp:pair-id: "robomda.ID.2" is a pair of ID) -->
  <xsl:key name="fp:in-pim" match="pim:*[@id or @via]"
      use="@id, tokenize(@via), @id[starts-with(., 'robomda.')] ! replace(., '^robomda\.(.+)\.[0-9]+$', '$1')"/>

  <!-- the warnings about $norm (the normalised XMI) and its PIM -->
  <xsl:function name="fp:report" as="empty-sequence()">
    <xsl:param name="norm" as="document-node()"/>
    <xsl:param name="pim" as="document-node()"/>
    <xsl:param name="root" as="element()"/>
    <!-- profiles are usually absent: the ancestor test only when some is there -->
    <xsl:variable name="profiles" as="element()*" select="$norm/descendant::*[@x:type eq 'Profile']"/>
    <!-- the elements of a kind robomda reads, and EA's exposed interfaces
         (<provided>, <required> of a classifier or port, with or without
         the xmi:idref of their interface) -->
    <xsl:variable name="candidates" as="element()*"
        select="$norm/descendant::*[@x:id][not(@href)]
                  [if (self::provided or self::required) then ../@x:type = $exposing-metas
                   else (map:contains($understood-map, string(@x:type)) and not(@x:idref))]
                  [not(@x:type = ('Property', 'Operation'))
                   or (map:contains($feature-owner-map, string(../@x:type)) and not(self::ownedEnd))]"/>
    <xsl:variable name="understood" as="element()*"
        select="if (empty($profiles)) then $candidates
                else $candidates[empty(ancestor::*[@x:type eq 'Profile'])]"/>
    <xsl:variable name="applications" as="element()*"
        select="$norm/x:XMI/*[not(namespace-uri() = ($U, $X))][@x:id]
                  [@*[starts-with(local-name(), 'base_')]]"/>
    <!-- (not an allocation of a deployment plan to a simulator or another
         middleware, nor its stereotype: IMP123 named it, dialects.xsl) -->
    <xsl:variable name="left-out" as="element()*"
        select="($understood, $applications)[empty(key('fp:in-pim', fp:id(.), $pim))]
                [not(fp:is-allocation(.) or (parent::x:XMI and (let $a := . return
                                                                 some $b in fp:base-ids($a) satisfies fp:is-allocation(fp:element($a, $b)))))]"/>
    <!-- stereotype applications on no element of the model (tools apply
         their own to diagrams kept in xmi:Extension): one warning per
         stereotype, naming every application -->
    <xsl:variable name="unbased" as="element()*"
        select="$left-out[parent::x:XMI]
                  [empty(for $a in . return
                         fp:base-ids($a) ! fp:element($a, .))]"/>
    <xsl:for-each select="$left-out except $unbased">
      <xsl:variable name="why" as="map(*)" select="fp:why-not-imported(., $root, $pim)"/>
      <xsl:sequence select="f:warn($why?code, fp:id(.), $why?message)"/>
    </xsl:for-each>
    <xsl:sequence select="fp:template-warnings($norm, $pim)"/>
    <xsl:sequence select="fp:pair-warnings($understood
        [@x:type = ('Usage', 'Realization', 'InterfaceRealization', 'ComponentRealization')]
        [count(fp:ref-ids(., 'client')) gt 1 or count(fp:ref-ids(., 'supplier')) gt 1]
        [exists(key('fp:in-pim', string(@x:id), $pim))], $pim)"/>
    <xsl:for-each-group select="$unbased" group-by="name()">
      <xsl:sequence select="f:warn('IMP115', fp:id(.), 'stereotype ' || local-name() || ' is applied '
          || count(current-group()) || ' time(s) to no element of the model (a tool''s own element, such as a'
          || ' diagram, or an element not in the file): not imported (xmi:ids='
          || string-join(current-group() ! fp:id(.), ',') || ')')"/>
    </xsl:for-each-group>
    <xsl:if test="empty(($pim//(pim:component | pim:class | pim:interface | pim:node))[1])">
      <!-- what the file holds, outside the profiles it defines (a
           profile's classes are not the model's) -->
      <xsl:variable name="held" as="element()*"
          select="$norm/descendant::*[@x:id][@x:type][not(starts-with(@x:type, '{'))]
                    [not(@x:type = ('Model', 'Comment'))]
                    [empty(ancestor::*[@x:type eq 'Profile'][not(. is $root)])]"/>
      <xsl:sequence select="f:warn('IMP030', fp:id($root), 'nothing to generate from: '
          || fp:label($root) || (if ($root/@x:type eq 'Profile') then ' is a profile, not a model: it' else '')
          || ' holds no component, class, interface or node'
          || (if ($root/@x:type ne 'Profile' and exists($held[@x:type = $classifier-metas][not(@href or @x:idref)]))
              then ' that robomda imports (the warnings above name those of the file)' else '')
          || (let $counts := fp:holds($norm, $held) return
              if (exists($counts)) then ' (it holds ' || string-join($counts, ', ') || ')' else ' (it is empty)')
          || '; robomda reads components, classes and interfaces (component diagram) and nodes'
          || ' (deployment diagram)')"/>
    </xsl:if>
  </xsl:function>

  <!-- IMP112 for each imported relationship of several clients or
       suppliers ($relationships) that names one robomda cannot use as such
       (a package as the client of a Usage ...): the pairs of the others
       are imported, that one is named -->
  <xsl:function name="fp:pair-warnings" as="empty-sequence()">
    <xsl:param name="relationships" as="element()*"/>
    <xsl:param name="pim" as="document-node()"/>
    <xsl:for-each select="$relationships">
      <xsl:variable name="meta" as="xs:string" select="@x:type"/>
      <xsl:variable name="clients" as="element()*"
          select="fp:targets(., 'client')[not(fp:meta(.) = ('Class', 'Component', 'Interface', 'Port', 'Collaboration')
                                               or exists(fp:interface-of(.)))]"/>
      <xsl:variable name="suppliers" as="element()*"
          select="fp:targets(., 'supplier')[empty(fp:interface-of(.))]
                    [not($meta = ('Realization', 'ComponentRealization') and fp:meta(.) = ('Class', 'Component'))]"/>
      <xsl:if test="exists($clients | $suppliers)">
        <xsl:sequence select="f:warn('IMP112', fp:id(.), fp:describe(.) || ' is imported for its other ends, not for '
            || string-join(($clients ! (fp:label(.) || ' (client)'), $suppliers ! (fp:label(.) || ' (supplier)')), ', ')
            || ': robomda reads it when its client is a class, component or port of the model and its supplier'
            || (if ($meta eq 'ComponentRealization') then ' a component, realized by a class or component'
                else ' an interface of the model'))"/>
      </xsl:if>
    </xsl:for-each>
  </xsl:function>

  <!-- IMP118 for each imported element that is a template (it owns a
       template signature) or binds one (a template binding): robomda
       generates no templates; the parameters' placeholders are no elements
       of the model (xmi-common.xsl), so this one warning names them -->
  <xsl:function name="fp:template-warnings" as="empty-sequence()">
    <xsl:param name="norm" as="document-node()"/>
    <xsl:param name="pim" as="document-node()"/>
    <!-- not of an interface whose binding its tool's profile reads (a
         communication pattern: dialects.xsl, fp:pattern) -->
    <xsl:for-each select="$norm/descendant::*[self::ownedTemplateSignature or self::templateBinding]/..
                          [exists(key('fp:in-pim', fp:id(.), $pim))][empty(fp:pattern(.))]">
      <xsl:variable name="parameters" as="xs:string*"
          select="ownedTemplateSignature/ownedParameter
                  ! (ownedParameteredElement, fp:targets(., 'parameteredElement'))[1]
                  ! (if (normalize-space(@name)) then string(@name) else fp:id(.))"/>
      <xsl:variable name="bound" as="xs:string*"
          select="templateBinding ! fp:targets(., 'signature')/.. ! fp:label(.)"/>
      <xsl:sequence select="f:warn('IMP118', fp:id(.), fp:describe(.) || ' is '
          || (if (exists(ownedTemplateSignature))
              then 'a template (parameters: ' || (if (exists($parameters)) then string-join($parameters, ', ') else 'none')
                   || ')' else '')
          || (if (exists(ownedTemplateSignature) and exists(templateBinding)) then ' and ' else '')
          || (if (exists(templateBinding))
              then 'bound to ' || (if (exists($bound)) then string-join($bound, ', ') else 'a template not in the file')
              else '')
          || ': robomda generates no templates, it imports the element with its own features only'
          || ' (a feature typed by a template parameter has no type robomda reads)')"/>
    </xsl:for-each>
  </xsl:function>

  <!-- "3 Profile", "12 Stereotype" ...: what a document holds ($held: its
       elements that count), the most frequent metaclasses first (at most 8) -->
  <xsl:function name="fp:holds" as="xs:string*">
    <xsl:param name="norm" as="document-node()"/>
    <xsl:param name="held" as="element()*"/>
    <xsl:variable name="groups" as="xs:string*">
      <xsl:for-each-group select="$held" group-by="string(@x:type)">
        <xsl:sort select="count(current-group())" order="descending"/>
        <xsl:sort select="current-grouping-key()"/>
        <xsl:sequence select="count(current-group()) || ' ' || current-grouping-key()"/>
      </xsl:for-each-group>
      <xsl:variable name="apps" as="xs:integer"
          select="count($norm/x:XMI/*[not(namespace-uri() = ($U, $X))][@*[starts-with(local-name(), 'base_')]])"/>
      <xsl:if test="$apps gt 0">
        <xsl:sequence select="$apps || ' stereotype application(s)'"/>
      </xsl:if>
    </xsl:variable>
    <xsl:sequence select="subsequence($groups, 1, 8)"/>
  </xsl:function>

  <!-- map { code, message }: why $e is not in the PIM -->
  <xsl:function name="fp:why-not-imported" as="map(*)">
    <xsl:param name="element" as="element()"/>
    <xsl:param name="root" as="element()"/>
    <xsl:param name="pim" as="document-node()"/>
    <xsl:variable name="meta" as="xs:string" select="fp:meta($element)"/>
    <xsl:variable name="what" as="xs:string" select="fp:describe($element)"/>
    <xsl:variable name="outside" as="xs:boolean" select="not($element/ancestor::* intersect $root)"/>
    <xsl:choose>
      <xsl:when test="not(namespace-uri($element) = ($U, $X, '')) and $element/parent::x:XMI">
        <xsl:variable name="bases" as="element()*"
            select="fp:base-ids($element) ! fp:element($element, .)"/>
        <xsl:sequence select="map { 'code': 'IMP115', 'message': 'stereotype ' || local-name($element)
            || (if (empty($bases)) then ' is applied to no element of the file'
                else ' is applied to ' || string-join($bases ! fp:label(.), ', ')
                     || (if (some $b in $bases satisfies exists(key('fp:in-pim', fp:id($b), $pim)))
                         then ', whose stereotypes the PIM does not keep'
                         else ', which robomda does not import'))
            || ': the stereotype is not imported' }"/>
      </xsl:when>
      <xsl:when test="$outside">
        <xsl:sequence select="map { 'code': 'IMP116', 'message': $what
            || ' is outside ' || fp:label($root) || ', the model robomda reads in this file: not imported' }"/>
      </xsl:when>
      <xsl:when test="$element/self::provided or $element/self::required">
        <xsl:variable name="named" as="element()?" select="fp:element($element, $element/@x:idref)"/>
        <xsl:sequence select="map { 'code': 'IMP119', 'message': 'the ' || local-name($element) || ' interface '''
            || $element/@name || ''' of ' || fp:label($element/..) || ' is not imported: '
            || (if (empty($element/@x:idref)) then 'it names no interface (an exposed interface Enterprise Architect'
                   || ' leaves unclassified)'
                else if (empty($named)) then 'the interface it names, ''' || $element/@x:idref || ''', is not in the file'
                else 'it names ' || fp:label($named) || ', which is not an interface')
            || '; classify it by an interface of the model' }"/>
      </xsl:when>
      <xsl:when test="$meta = ('Property', 'Operation') and $element/../@x:type eq 'Collaboration'">
        <xsl:sequence select="map { 'code': 'IMP116', 'message': $what || ' is not imported: robomda reads a'
            || ' Collaboration only as the protocol that types a port, not its roles (the context of an'
            || ' interaction)' }"/>
      </xsl:when>
      <xsl:when test="$meta eq 'Connector'">
        <xsl:sequence select="map { 'code': 'IMP110', 'message': $what || ' is not imported: ' || (
            if ($element/end/(role | partWithPort)/@href) then 'an end is in another model'
            else if (count($element/end[exists(fp:targets(., 'role'))]) lt 2) then 'it has fewer than two ends in the model'
            else (let $owner := if ($element/self::ownedConnector and $element/../@x:type = ('Class', 'Component', 'Interface'))
                                then $element/.. else fp:element($element, fp:connector-owner($element)),
                      $problems := $element/end[exists(fp:targets(., 'role'))]
                                   ! (let $end := . return fp:end-path($end, $owner)?problem
                                      ! ('its end on ' || fp:label(fp:targets($end, 'role')[1]) || ' cannot be followed: ' || .))
                  return if (exists($problems)) then string-join($problems, '; ')
                         else 'no class or component owns the parts it joins')) }"/>
      </xsl:when>
      <xsl:when test="$meta = ('Dependency', 'Abstraction')">
        <xsl:sequence select="map { 'code': 'IMP111', 'message': $what || ' is not imported: ' || (
            if (fp:is-start-after($element)) then 'it has no client or no supplier in this model'
            else if (fp:drives-device($element)) then 'it has no client in this model'
            else 'robomda reads a dependency only as a deployment-sequence constraint'
                 || ' (stereotype StartAfter, or named startAfter) or as a part driving a Device (its supplier); docs/profile.md') }"/>
      </xsl:when>
      <xsl:when test="$meta = ('Usage', 'Realization', 'InterfaceRealization', 'ComponentRealization')">
        <xsl:sequence select="map { 'code': 'IMP112', 'message': $what || ' is not imported: '
            || 'robomda reads it when its client is a class, component or port of the model and its supplier'
            || (if ($meta eq 'ComponentRealization') then ' a component, realized by a class or component'
                else ' an interface of the model')
            || ' (client: ' || fp:ends($element, ('client')) || '; supplier: '
            || fp:ends($element, ('supplier', 'contract', 'realizingClassifier')) || ')' }"/>
      </xsl:when>
      <xsl:when test="$meta = ('Deployment', 'Manifestation')">
        <xsl:sequence select="map { 'code': 'IMP113', 'message': $what || ' is not imported: it '
            || (if ($meta eq 'Deployment') then 'deploys nothing of the model onto a node'
                else 'manifests nothing of the model in an artifact')
            || ' (client: ' || fp:ends($element, ('client')) || '; supplier: '
            || fp:ends($element, ('supplier', 'deployedArtifact', 'utilizedElement')) || ')' }"/>
      </xsl:when>
      <xsl:when test="$meta eq 'CommunicationPath'">
        <xsl:sequence select="map { 'code': 'IMP114', 'message': $what
            || ' is not imported: it does not join two nodes' }"/>
      </xsl:when>
      <xsl:otherwise>
        <xsl:sequence select="map { 'code': 'IMP116', 'message': $what || ' is not imported: robomda does not read a '
            || $meta || ' owned by ' || (if ($element/..) then fp:label($element/..) else 'nothing') }"/>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <!-- the labels of what $e refers to by the properties $props -->
  <xsl:function name="fp:ends" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:param name="props" as="xs:string*"/>
    <xsl:variable name="ids" as="xs:string*" select="$props ! fp:ref-ids($element, .)"/>
    <xsl:variable name="hrefs" as="xs:string*" select="$element/*[local-name() = $props]/@href/string()"/>
    <xsl:sequence select="if (empty(($ids, $hrefs))) then 'none'
        else string-join(($ids ! (let $t := fp:element($element, .) return
                                  if ($t) then fp:label($t) else '''' || . || ''' (not in the file)'),
                          $hrefs ! ('''' || . || '''')), ', ')"/>
  </xsl:function>
</xsl:stylesheet>
